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
import sitcov.judge.Simulator;
import sitcov.oracle.RunResult;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class TraceWriterTest {

    private static final WorldMap MAP = MapGenerator.generate(3);
    private static final long INTERNAL_SEED = 100;
    private static final String HEADER = "external_seed,internal_seed,tick,x,y,heading,speed,lane,overtaking_stage,"
            + "crossing_junction,waiting_at_junction,steered_by,accidents_so_far";

    private static RunResult trace(Path file) throws IOException {
        try (TraceWriter writer = new TraceWriter(file, MAP.seed(), INTERNAL_SEED)) {
            return Simulator.run(MAP, INTERNAL_SEED, Set.of(), writer).result();
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
            assertEquals(13, fields.length, lines.get(i));
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
        Simulator.run(MAP, INTERNAL_SEED, Set.of(), writer);
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
