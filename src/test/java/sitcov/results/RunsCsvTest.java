package sitcov.results;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.judge.Detection;
import sitcov.judge.FaultOutcome;
import sitcov.judge.RunSummary;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;

class RunsCsvTest {
    private static final ExperimentConfig CONFIG = new ExperimentConfig("csv", 1, 10, 1, FaultSet.parse("14,19"),
            BudgetKind.TICKS, GridDefinition.paper());
    private static final RunsCsv CSV = new RunsCsv(CONFIG);

    static MapRun map(int index, MapId id) {
        RunSummary safe = new RunSummary(Outcome.TARGET_REACHED, 321, List.of(0L, 0L, 0L, 0L, 0L));
        RunSummary crash = new RunSummary(Outcome.TIMEOUT, 5000, List.of(0L, 1L, 2L, 0L, 1L));
        return new MapRun(0, "random", index, index * 3, id, 77, -5, 104, List.of(12.5, 200.0, 31.25), safe, List.of(
                new FaultOutcome(Fault.TARGET_LANE_CHECK_SKIPPED, crash, true, true, 44, Detection.FOUND,
                        Optional.of(AccidentType.LEAVEROAD), true),
                new FaultOutcome(Fault.ONCOMING_AT_HALF_SPEED, safe, true, false, -1, Detection.REACHED_NO_EFFECT,
                        Optional.empty(), false)));
    }

    @Test
    void aBlockHasTheFaultFreeRowThenOneRowPerFaultAsWorkedOutByHand() {
        String block = CSV.block(map(2, new MapId.Seeded(77)));
        assertEquals("0,random,2,6,seed:77,77,-5,104,12.500,200.000,31.250,NONE,TARGET_REACHED,321,0,0,0,0,0,,,,,,\n"
                + "0,random,2,6,seed:77,77,-5,104,12.500,200.000,31.250,14,TIMEOUT,5000,0,1,2,0,1,true,true,44,FOUND,LEAVEROAD,true\n"
                + "0,random,2,6,seed:77,77,-5,104,12.500,200.000,31.250,19,TARGET_REACHED,321,0,0,0,0,0,true,false,-1,"
                + "REACHED_NO_EFFECT,,false\n", block);
    }

    @Test
    void readingTheBlocksBackGivesTheSameMaps() {
        List<MapRun> maps = List.of(map(0, new MapId.Seeded(77)), map(1, new MapId.Situation("edited-1")));
        String text = CSV.header() + "\n" + CSV.block(maps.get(0)) + CSV.block(maps.get(1));
        assertEquals(maps, CSV.read(text, "runs.csv"));
    }

    @Test
    void aBlockCutShortByAKillIsLeftOut() {
        String whole = CSV.header() + "\n" + CSV.block(map(0, new MapId.Seeded(77)));
        String second = CSV.block(map(1, new MapId.Seeded(78)));
        for (int cut : new int[] {1, second.indexOf('\n') + 1, second.length() - 1}) {
            assertEquals(1, CSV.read(whole + second.substring(0, cut), "runs.csv").size(), "cut at " + cut);
        }
    }

    @Test
    void aMalformedRowInsideTheFileIsRefusedNamingItsLine() {
        String block = CSV.block(map(0, new MapId.Seeded(77)));
        String broken = CSV.header() + "\n" + block.replace(",FOUND,", ",FUND,") + CSV.block(map(1, new MapId.Seeded(78)));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CSV.read(broken, "runs.csv"));
        assertTrue(e.getMessage().startsWith("runs.csv:3: "), e.getMessage());
        IllegalArgumentException header = assertThrows(IllegalArgumentException.class,
                () -> CSV.read("method,replication\n" + block, "old/runs.csv"));
        assertTrue(header.getMessage().startsWith("old/runs.csv:1: the header lacks the columns 'driver', 'map_index'"),
                header.getMessage());
        assertTrue(header.getMessage().contains("has the column 'method' this sitcov does not know"), header.getMessage());
    }

    @Test
    void aFolderWrittenBeforeAnAccidentTypeExistedIsRefusedNamingTheMissingColumn() {
        String block = CSV.block(map(0, new MapId.Seeded(77)));
        // An older runs.csv without the timeout column: its rows have one value fewer, in the header and every row.
        int at = List.of(CSV.header().split(",")).indexOf("timeout");
        String older = String.join("\n", CSV.header().replace(",timeout,", ","),
                dropColumn(block.split("\n")[0], at), dropColumn(block.split("\n")[1], at),
                dropColumn(block.split("\n")[2], at)) + "\n";
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CSV.read(older, "old/runs.csv"));
        assertTrue(e.getMessage().startsWith("old/runs.csv:1: the header lacks the column 'timeout' this sitcov reads"),
                e.getMessage());
    }

    @Test
    void columnsInAnotherOrderAreReadByTheirNames() {
        MapRun run = map(0, new MapId.Seeded(77));
        List<String> names = List.of(CSV.header().split(","));
        int a = names.indexOf("reached");
        int b = names.indexOf("effective");
        // Swap two columns of equal type whose values differ in the second fault's row (true, false).
        String swapped = String.join("\n", List.of((CSV.header() + "\n" + CSV.block(run)).split("\n")).stream()
                .map(line -> swap(line, a, b)).toList()) + "\n";
        assertEquals(List.of(run), CSV.read(swapped, "runs.csv"));
    }

    private static String dropColumn(String line, int at) {
        List<String> values = new java.util.ArrayList<>(List.of(line.split(",", -1)));
        values.remove(at);
        return String.join(",", values);
    }

    private static String swap(String line, int a, int b) {
        String[] values = line.split(",", -1);
        String t = values[a];
        values[a] = values[b];
        values[b] = t;
        return String.join(",", values);
    }
}
