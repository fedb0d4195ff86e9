package sitcov.results;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.zip.CRC32;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.Shard;
import sitcov.faults.FaultSet;

class JournalCheckTest {
    private static Manifest manifest(long seed) {
        return new Manifest(new ExperimentConfig("checks", seed, 10, 2, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper()), "test", Shard.WHOLE, false, false);
    }

    private static final JournalCheck CHECK = JournalCheck.of(manifest(1));
    private static final String ROWS = "0,random,12,3,40,1,ticks\n1,random,9,2,31,2,candidates\n";

    private static List<String> lines(String text) {
        return CsvLines.complete(text);
    }

    @Test
    void aCheckIsTheCrc32OfTheRowKeyedByTheExperiment() {
        CRC32 crc = new CRC32();
        crc.update(manifest(1).experimentDigest().getBytes(StandardCharsets.UTF_8));
        crc.update("0,random,12,3,40,1,ticks".getBytes(StandardCharsets.UTF_8));
        String signed = CHECK.rows("0,random,12,3,40,1,ticks\n");
        assertEquals("0,random,12,3,40,1,ticks," + String.format("%08x", crc.getValue()) + "\n", signed);
    }

    @Test
    void checkedRowsReadBackWithoutTheirCheckColumns() {
        String text = CHECK.header(DriversCsv.HEADER, false) + "\n" + CHECK.rows(ROWS);
        assertEquals(DriversCsv.HEADER + ",check", lines(text).get(0));
        assertEquals(lines(DriversCsv.HEADER + "\n" + ROWS), CHECK.read(lines(text), "drivers.csv", false, "fix").lines());
        String runs = CHECK.header("a,b", true) + "\n" + CHECK.rows("1,2\n3,4\n", "0badcafe");
        JournalCheck.Checked read = CHECK.read(lines(runs), "runs.csv", true, "fix");
        assertEquals(List.of("a,b", "1,2", "3,4"), read.lines());
        assertEquals(List.of("0badcafe", "0badcafe"), read.situationChecks());
    }

    @Test
    void aChangedRowIsRefusedNamingItsLine() {
        String text = CHECK.header(DriversCsv.HEADER, false) + "\n" + CHECK.rows(ROWS);
        String edited = text.replace("1,random,9,2,31,", "1,random,9,2,32,");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CHECK.read(lines(edited), "drivers.csv", false, "put it back"));
        assertTrue(e.getMessage().startsWith("drivers.csv:3: this row was changed after sitcov wrote it (it does not match"
                + " its check); put it back"), e.getMessage());
    }

    @Test
    void rowsWrittenForAnotherExperimentMatchNoneOfItsRows() {
        String other = CHECK.header(DriversCsv.HEADER, false) + "\n" + JournalCheck.of(manifest(2)).rows(ROWS);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CHECK.read(lines(other), "drivers.csv", false, "fix"));
        assertTrue(e.getMessage().contains("drivers.csv:2: ") && e.getMessage().contains("no row matches this manifest"),
                e.getMessage());
    }

    @Test
    void aHeaderThatLostItsCheckColumnsIsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CHECK.read(lines(DriversCsv.HEADER + "\n" + ROWS), "drivers.csv", false, "fix"));
        assertTrue(e.getMessage().startsWith("drivers.csv:1: the header lacks the columns 'check'"), e.getMessage());
    }

    @Test
    void aRowCutShortByAKillIsLeftOutNotRefused() {
        String text = CHECK.header(DriversCsv.HEADER, false) + "\n" + CHECK.rows(ROWS);
        String cut = text.substring(0, text.length() - 5);
        assertEquals(2, CHECK.read(lines(cut), "drivers.csv", false, "fix").lines().size());
    }

    @Test
    void aFolderWrittenBeforeChecksIsReadAndWrittenAsItIs() {
        Manifest checked = manifest(1);
        Manifest older = new Manifest(checked.config(), checked.version(), checked.shard(), false, false, false);
        JournalCheck none = JournalCheck.of(older);
        assertEquals(ROWS, none.rows(ROWS, ""));
        assertEquals(DriversCsv.HEADER, none.header(DriversCsv.HEADER, false));
        assertEquals(lines(DriversCsv.HEADER + "\n" + ROWS),
                none.read(lines(DriversCsv.HEADER + "\n" + ROWS), "drivers.csv", false, "fix").lines());
        assertTrue(older.lines().stream().noneMatch(l -> l.startsWith("checks=")), older.lines().toString());
    }
}
