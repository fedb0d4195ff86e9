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
import sitcov.oracle.Margins;
import sitcov.oracle.NearMiss;
import sitcov.oracle.Outcome;

class RunsCsvTest {
    private static final ExperimentConfig CONFIG = new ExperimentConfig("csv", 1, 10, 1, FaultSet.parse("14,19"),
            BudgetKind.TICKS, GridDefinition.paper());
    private static final RunsCsv CSV = new RunsCsv(CONFIG);

    static MapRun map(int index, MapId id) {
        double inf = Double.POSITIVE_INFINITY;
        RunSummary safe = new RunSummary(Outcome.TARGET_REACHED, 321, List.of(0L, 0L, 0L, 0L, 0L), new Margins(
                List.of(2.5, inf, 0.3, 0.8, 12.25, 40.0), List.of(inf, 2.5, 0.3, 0.8, 4679.0)));
        RunSummary crash = new RunSummary(Outcome.TIMEOUT, 5000, List.of(0L, 1L, 2L, 0L, 1L), new Margins(
                List.of(-0.05, inf, -0.1234, 0.5, 0.0, inf), List.of(inf, -0.05, -0.1234, 0.5, 0.0)));
        return new MapRun(0, "random", index, index * 3, id, 77, -5, 104, List.of(12.5, 200.0, 31.25), safe, List.of(
                new FaultOutcome(new sitcov.judge.Variant.Seeded(Fault.TARGET_LANE_CHECK_SKIPPED), crash, true, true, 44, Detection.FOUND,
                        Optional.of(sitcov.oracle.Failure.LEAVEROAD), true),
                new FaultOutcome(new sitcov.judge.Variant.Seeded(Fault.ONCOMING_AT_HALF_SPEED), safe, true, false, -1, Detection.REACHED_NO_EFFECT,
                        Optional.empty(), false)));
    }

    @Test
    void aBlockHasTheFaultFreeRowThenOneRowPerFaultAsWorkedOutByHand() {
        String block = CSV.block(map(2, new MapId.Seeded(77)));
        String safe = ",2.5000,inf,0.3000,0.8000,12.2500,40.0000,inf,2.5000,0.3000,0.8000,4679.0000";
        assertEquals("0,random,2,6,seed:77,77,-5,104,12.500,200.000,31.250,NONE,TARGET_REACHED,321,0,0,0,0,0,,,,,,"
                + safe + "\n"
                + "0,random,2,6,seed:77,77,-5,104,12.500,200.000,31.250,14,TIMEOUT,5000,0,1,2,0,1,true,true,44,FOUND,LEAVEROAD,true"
                + ",-0.0500,inf,-0.1234,0.5000,0.0000,inf,inf,-0.0500,-0.1234,0.5000,0.0000\n"
                + "0,random,2,6,seed:77,77,-5,104,12.500,200.000,31.250,19,TARGET_REACHED,321,0,0,0,0,0,true,false,-1,"
                + "REACHED_NO_EFFECT,,false" + safe + "\n", block);
    }

    @Test
    void aFolderWrittenBeforeMarginsWereKeptReadsThemAsUnknown() {
        int kept = NearMiss.values().length + AccidentType.values().length;
        String text = CSV.header() + "\n" + CSV.block(map(0, new MapId.Seeded(77)));
        StringBuilder old = new StringBuilder();
        for (String line : text.split("\n")) {
            String[] cells = line.split(",", -1);
            old.append(String.join(",", List.of(cells).subList(0, cells.length - kept))).append('\n');
        }
        MapRun read = CSV.read(old.toString(), "old/runs.csv").get(0);
        assertEquals(Margins.UNKNOWN, read.faultFree().margins());
        assertEquals(Margins.UNKNOWN, read.faults().get(0).run().margins());
        assertEquals(map(0, new MapId.Seeded(77)).faultFree().accidents(), read.faultFree().accidents());
    }

    @Test
    void aKeptMarginReadsBackAsTheSameNumber() {
        java.util.Random random = new java.util.Random(30);
        for (int i = 0; i < 100_000; i++) {
            double v = Margins.kept((random.nextDouble() - 0.3) * Math.pow(10, random.nextInt(12)));
            assertEquals(v, RunsCsv.margin(RunsCsv.margin(v)), "seed 30, draw " + i);
        }
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
