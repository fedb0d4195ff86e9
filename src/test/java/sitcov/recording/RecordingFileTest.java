package sitcov.recording;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.zip.GZIPInputStream;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinCar;
import sitcov.control.ControllerFailure;
import sitcov.geom.Compass;
import sitcov.judge.RunObserver;
import sitcov.judge.RunRecord;
import sitcov.judge.Simulator;
import sitcov.oracle.Outcome;
import sitcov.vehicles.CommandLog;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class RecordingFileTest {
    @TempDir
    Path dir;

    private static Recording recordingOf(RunRecord run) {
        return new Recording(new Recording.RunKey(0, "random", 3, 2), run.result().externalSeed(),
                run.result().internalSeed(), run.result().outcome(), run.result().ticks(), run.commands());
    }

    @Test
    void aRunWrittenAndReadBackReplaysToTheSameResult() throws Exception {
        WorldMap map = MapGenerator.generate(5);
        RunRecord live = Simulator.run(map, 7, Set.of(), RunObserver.NONE, BuiltinCar.FACTORY);
        Path file = dir.resolve("run.jsonl.gz");
        Files.write(file, RecordingFile.write(recordingOf(live)));
        Recording back = RecordingFile.read(file);
        assertEquals(live.commands().ticks(), back.commands().ticks());
        assertTrue(back.commands().reports() > 0, "the builtin car reports on itself, and the report is kept");
        RunRecord replayed = Simulator.replay(map, 7, back.commands(), back.stopAfter(), RunObserver.NONE);
        assertEquals(live.result(), replayed.result(), "the commands are the run");
        assertArrayEquals(Files.readAllBytes(file), RecordingFile.write(recordingOf(replayed)),
                "a replay records the same bytes as the live run");
    }

    @Test
    void clampingJunctionRequestsReportsAndAFailureComeBackBitForBit() throws Exception {
        CommandLog log = new CommandLog();
        log.report(0, new CommandLog.Report(true, false, true, Compass.WEST, "PASSING", "traffic \"ahead\"", null));
        log.release(2);
        log.claim(4);
        log.command(2.5, -15.0);
        log.clamped(Double.NaN, Double.POSITIVE_INFINITY);
        log.command(0.1 + 0.2, 1e-300);
        log.failed(ControllerFailure.Kind.TIMEOUT, "no answer\nin 100 ms");
        Recording r = new Recording(new Recording.RunKey(1, "coverage-filter", 0, 0), -4, 9, Outcome.CONTROLLER_TIMEOUT, 3,
                log);
        Path file = dir.resolve("r.jsonl.gz");
        Files.write(file, RecordingFile.write(r));
        Recording back = RecordingFile.read(file);
        CommandLog b = back.commands();
        assertEquals(r.key(), back.key());
        assertEquals(3, b.ticks());
        assertEquals(0.1 + 0.2, b.speed(1));
        assertEquals(1e-300, b.steering(1));
        assertTrue(Double.isNaN(b.askedSpeed(0)) && b.askedSteering(0) == Double.POSITIVE_INFINITY);
        assertEquals(2, b.requests());
        assertTrue(!b.isClaim(0) && b.requestJunction(0) == 2 && b.isClaim(1) && b.requestJunction(1) == 4);
        assertEquals(log.report(0), b.report(0));
        assertEquals(2, b.failedAt());
        assertEquals("no answer\nin 100 ms", b.failureMessage());
        assertEquals(ControllerFailure.Kind.TIMEOUT, b.failureKind());
    }

    @Test
    void theSensorsTheControllerTookComeBackAndARecordingWithoutThemReadsAsAProgramsDefault() throws Exception {
        RunRecord live = Simulator.run(MapGenerator.generate(5), 7, Set.of(), RunObserver.NONE, BuiltinCar.FACTORY);
        assertEquals(sitcov.control.Sensor.all(), live.commands().sensors(), "the builtin car is handed every sensor");
        live.commands().sensors(java.util.EnumSet.of(sitcov.control.Sensor.RADAR, sitcov.control.Sensor.LIDAR));
        Path file = dir.resolve("sensors.jsonl.gz");
        Files.write(file, RecordingFile.write(recordingOf(live)));
        assertEquals(java.util.EnumSet.of(sitcov.control.Sensor.RADAR, sitcov.control.Sensor.LIDAR),
                RecordingFile.read(file).commands().sensors());
        String text = RecordingText.format(recordingOf(live));
        assertTrue(text.startsWith("{") && text.contains(",\"sensors\":[\"radar\",\"lidar\"]}\n"), text.substring(0, 300));
        // as a recording written before sensors were recorded: the header without them
        String older = text.replace(",\"sensors\":[\"radar\",\"lidar\"]", "");
        assertEquals(sitcov.control.Sensor.reported(), RecordingText.parse(older, "older").commands().sensors());
    }

    @Test
    void aRecordingChangedByHandIsRefusedNamingItsFile() throws Exception {
        WorldMap map = MapGenerator.generate(5);
        Path file = dir.resolve("run.jsonl.gz");
        Files.write(file, RecordingFile.write(recordingOf(Simulator.run(map, 7, Set.of(), RunObserver.NONE,
                BuiltinCar.FACTORY))));
        String text;
        try (GZIPInputStream in = new GZIPInputStream(Files.newInputStream(file))) {
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        String edited = text.replaceFirst("\"v\":0\\.1,", "\"v\":0.2,");
        assertTrue(!edited.equals(text), "the edit changes a command");
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (GZIPOutputStream out = new GZIPOutputStream(bytes)) {
            out.write(edited.getBytes(StandardCharsets.UTF_8));
        }
        Files.write(file, bytes.toByteArray());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> RecordingFile.read(file));
        assertTrue(e.getMessage().contains(file.toString()) && e.getMessage().contains("changed"), e.getMessage());
        Files.writeString(file, "not gzip");
        e = assertThrows(IllegalArgumentException.class, () -> RecordingFile.read(file));
        assertTrue(e.getMessage().contains("not a gzip file"), e.getMessage());
    }
}
