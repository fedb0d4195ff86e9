package sitcov.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinRuns;
import sitcov.geom.Box;
import sitcov.geom.BoxGap;
import sitcov.judge.Simulator;
import sitcov.oracle.AccidentType;
import sitcov.oracle.NearMiss;
import sitcov.oracle.RunResult;
import sitcov.world.Dimensions;
import sitcov.world.MapGenerator;
import sitcov.world.ParkedCar;
import sitcov.world.WorldMap;

class TraceWriterTest {

    private static final WorldMap MAP = MapGenerator.generate(3);
    private static final long INTERNAL_SEED = 100;
    private static final String HEADER = "external_seed,internal_seed,tick,x,y,heading,speed,lane,overtaking_stage,"
            + "crossing_junction,waiting_at_junction,steered_by,accidents_so_far,"
            + "near_moving_gap,near_parked_gap,near_road_edge,near_centre_line,near_time_to_collision,"
            + "near_post_encroachment,rho_clashwithobstacle,rho_clashwithothercar,rho_leaveroad,rho_crosscentreline,"
            + "rho_timeout";
    private static final int COLUMNS = 24;

    private static RunResult trace(Path file) throws IOException {
        try (TraceWriter writer = new TraceWriter(file, MAP.seed(), INTERNAL_SEED)) {
            return BuiltinRuns.run(MAP, INTERNAL_SEED, Set.of(), writer).result();
        }
    }

    @Test
    void writesAHeaderAndOneRowPerTick(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("trace.csv");
        RunResult result = trace(file);
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        assertEquals(result.ticks() + 1, lines.size());
        assertEquals(HEADER, lines.get(0));
        assertEquals(HEADER, TraceWriter.HEADER);
    }

    @Test
    void eachRowNamesBothSeedsItsTickAndTheAccidentsSoFar(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("trace.csv");
        RunResult result = trace(file);
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        for (int i = 1; i < lines.size(); i++) {
            String[] fields = lines.get(i).split(",", -1);
            assertEquals(COLUMNS, fields.length, lines.get(i));
            assertEquals(String.valueOf(MAP.seed()), fields[0]);
            assertEquals(String.valueOf(INTERNAL_SEED), fields[1]);
            assertEquals(String.valueOf(i - 1), fields[2]);
            for (int f = 3; f <= 6; f++) {
                assertTrue(fields[f].matches("-?\\d+\\.\\d{4}"), "field " + f + " of row " + i + ": " + fields[f]);
            }
            assertTrue(fields[9].equals("true") || fields[9].equals("false"), lines.get(i));
        }
        String[] last = lines.get(lines.size() - 1).split(",", -1);
        assertEquals(String.valueOf(result.accidents().size()), last[12]);
    }

    @Test
    void theOldColumnsComeFirstAndUnchanged() {
        assertTrue(HEADER.startsWith(TraceWriter.POSE_HEADER + ","));
        assertEquals(13, TraceWriter.POSE_HEADER.split(",").length);
    }

    /** The trace's last row holds the run's margins exactly as runs.csv writes them. */
    @Test
    void theLastRowHoldsTheRunsNearMissesAndRobustnessAsRunsCsvHasThem(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("trace.csv");
        RunResult result = trace(file);
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        String[] last = lines.get(lines.size() - 1).split(",", -1);
        int at = 13;
        for (NearMiss m : NearMiss.values()) {
            assertEquals(csv(result.margins().least(m)), last[at++], m.column());
        }
        for (AccidentType t : AccidentType.values()) {
            assertEquals(csv(result.margins().robustness(t)), last[at++], t.robustnessColumn());
        }
    }

    private static String csv(double v) {
        return Double.isNaN(v) ? "" : v == Double.POSITIVE_INFINITY ? "inf" : String.format(java.util.Locale.ROOT, "%.4f", v);
    }

    /**
     * Map 1's car passes a parked car about half a metre off. The gap, worked out again from each
     * row's pose (the footprint behind the front centre) and the parked cars' footprints, never rises
     * above the least-so-far column, which takes each new least as the row reaches it.
     */
    @Test
    void theParkedGapColumnIsTheLeastGapSoFarWorkedOutFromThePoses(@TempDir Path dir) throws IOException {
        WorldMap map = MapGenerator.generate(1);
        Path file = dir.resolve("one.csv");
        try (TraceWriter writer = new TraceWriter(file, map.seed(), 1)) {
            BuiltinRuns.run(map, 1, Set.of(), writer);
        }
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        int column = List.of(lines.get(0).split(",")).indexOf("near_parked_gap");
        List<Box> parked = map.layout().parkedCars().stream().map(ParkedCar::footprint).toList();
        assertFalse(parked.isEmpty());
        double least = Double.POSITIVE_INFINITY;
        for (int i = 1; i < lines.size(); i++) {
            String[] f = lines.get(i).split(",", -1);
            Box car = Box.behind(Double.parseDouble(f[3]), Double.parseDouble(f[4]), Double.parseDouble(f[5]),
                    Dimensions.AUTONOMOUS_CAR_LENGTH, Dimensions.AUTONOMOUS_CAR_WIDTH);
            for (Box p : parked) {
                least = Math.min(least, BoxGap.signedDistance(car, p));
            }
            // the pose is written to 4 decimals (heading in degrees), the gap kept to 4: a few 1e-4 m apart at most
            assertEquals(least, Double.parseDouble(f[column]), 1e-3, "row " + i);
        }
        assertTrue(least > 0 && least < 1, "a near miss, not a clash: " + least);
    }

    @Test
    void theSameRunTracedTwiceGivesByteIdenticalFiles(@TempDir Path dir) throws IOException {
        Path first = dir.resolve("first.csv");
        Path second = dir.resolve("second.csv");
        trace(first);
        trace(second);
        assertEquals(-1L, Files.mismatch(first, second));
        byte[] bytes = Files.readAllBytes(first);
        assertFalse(new String(bytes, StandardCharsets.UTF_8).contains("\r"), "only '\\n' line ends");
        assertEquals('\n', bytes[bytes.length - 1]);
    }

    @Test
    void theFileAppearsOnlyWhenClosedAndNoTemporaryFileIsLeft(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("trace.csv");
        TraceWriter writer = new TraceWriter(file, MAP.seed(), INTERNAL_SEED);
        BuiltinRuns.run(MAP, INTERNAL_SEED, Set.of(), writer);
        assertFalse(Files.exists(file), "visible before close()");
        writer.close();
        writer.close();
        assertTrue(Files.size(file) > HEADER.length());
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList());
        }
    }

    @Test
    void replacesAnOlderTraceOfTheSameName(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("trace.csv");
        Files.writeString(file, "stale\n");
        trace(file);
        assertEquals(HEADER, Files.readAllLines(file).get(0));
    }
}
