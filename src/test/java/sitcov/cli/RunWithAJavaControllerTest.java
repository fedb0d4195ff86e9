package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.control.Channel;
import sitcov.control.Command;
import sitcov.control.Controller;
import sitcov.control.ControllerFailure;
import sitcov.control.Observation;
import sitcov.protocol.JavaControllers;

/**
 * A controller written in Java and added in one class and one line: an experiment tests it, judges
 * its variants against it, counts a variant's crashes as its failures, and refuses the builtin car's
 * seeded faults, which cannot act on it.
 */
class RunWithAJavaControllerTest {
    /** Keeps its lane by the ground truth it reads, at a walking pace; brakes for nothing. */
    static final class LaneKeeper implements Controller {
        @Override
        public void step(Observation now, Command out) {
            double offset = now.channel(Channel.LANE_OFFSET);
            double error = now.channel(Channel.HEADING_ERROR);
            out.speed(0.6).steering(Double.isNaN(offset) ? 0 : -error + 8 * offset);
        }
    }

    /** The lane keeper with a planted bug: it throws at tick 20, a crash of a controller in process. */
    static final class CrashesAtTwenty implements Controller {
        private final LaneKeeper keeper = new LaneKeeper();

        @Override
        public void step(Observation now, Command out) {
            if (now.tick() == 20) {
                throw new IllegalStateException("planted bug");
            }
            keeper.step(now, out);
        }
    }

    /** Asks for more than the car can do every tick: 3 m a tick, where the world gives at most 2.5. */
    static final class Speeder implements Controller {
        @Override
        public void step(Observation now, Command out) {
            out.speed(3).steering(0);
        }
    }

    /** Fails to answer on its first tick, as a controller that gives no command in time does. */
    static final class NeverAnswers implements Controller {
        @Override
        public void step(Observation now, Command out) {
            throw new ControllerFailure(ControllerFailure.Kind.TIMEOUT, "no command");
        }
    }

    @BeforeAll
    static void register() {
        JavaControllers.register("test-lane-keeper", run -> new LaneKeeper());
        JavaControllers.register("test-crashes-at-20", run -> new CrashesAtTwenty());
        JavaControllers.register("test-never-answers", run -> new NeverAnswers());
        JavaControllers.register("test-speeder", run -> new Speeder());
    }

    private static Path preset(Path dir, String extra) throws IOException {
        Path p = dir.resolve("java.properties");
        Files.writeString(p, "master_seed=3\ncandidates=6\nreplications=2\nbudget=ticks\ndrivers=coverage-filter,random\n"
                + "grid=experiments/paper-grid.txt\ncontroller=java:test-lane-keeper\n" + extra);
        return p;
    }

    private static List<String> rows(Path folder) throws IOException {
        return Files.readAllLines(folder.resolve("runs.csv"));
    }

    @Test
    void aVariantThatCrashesWhereTheReferenceDoesNotIsFoundOnEveryMapByItsControllerError(@TempDir Path dir)
            throws IOException {
        Path out = dir.resolve("out");
        CliRunner r = CliRunner.run("run", preset(dir, "variants=java:test-crashes-at-20\n").toString(), "--out",
                out.toString(), "--threads", "2");
        assertEquals(ExitCode.OK, r.exitCode(), r.err() + r.out());
        List<String> header = List.of(rows(out).get(0).split(","));
        int variant = header.indexOf("fault");
        int outcome = header.indexOf("outcome");
        int detection = header.indexOf("detection");
        int failure = header.indexOf("new_accident");
        int reason = header.indexOf("controller_failure");
        int crashed = 0;
        long referenceTicks = -1;
        for (String line : rows(out).subList(1, rows(out).size())) {
            String[] cells = line.split(",", -1);
            if (cells[variant].equals("NONE")) {
                assertFalse(cells[outcome].startsWith("CONTROLLER"), "the reference never crashes: " + line);
                referenceTicks = Long.parseLong(cells[header.indexOf("ticks")]);
                continue;
            }
            assertEquals("1", cells[variant], "the only variant takes id 1");
            if (referenceTicks <= 20) {
                // the reference arrived before tick 20: so did the variant, driving exactly as it does
                assertEquals("REACHED_NO_EFFECT", cells[detection], line);
                continue;
            }
            crashed++;
            assertEquals("CONTROLLER_ERROR", cells[outcome], line);
            assertEquals("21", cells[header.indexOf("ticks")], "it crashed in tick 20, the 21st: " + line);
            assertEquals("FOUND", cells[detection], line);
            assertEquals("CONTROLLER_ERROR", cells[failure], line);
            assertTrue(cells[reason].contains("planted bug"), "the reason is kept: " + line);
        }
        assertTrue(crashed >= 6, "the variant crashed wherever the reference drove past tick 20, got " + crashed);
        String verdict = Files.readString(out.resolve("verdict.txt"));
        assertTrue(verdict.startsWith("Controller failures"), verdict);
        assertTrue(verdict.contains("variant 1 (test-crashes-at-20) on " + crashed + " (" + crashed
                + " CONTROLLER_ERROR)"), verdict);
        String manifest = Files.readString(out.resolve("manifest.properties"));
        assertTrue(manifest.contains("variants=java:test-crashes-at-20\n") && !manifest.contains("faults="), manifest);
        // the variant's crash is recorded: replay shows it from its commands, the Java controller not run
        CliRunner replay = CliRunner.run("replay", out.toString(), "--row", "2", "--png",
                dir.resolve("row-2.png").toString());
        assertEquals(ExitCode.OK, replay.exitCode(), replay.err());
        assertTrue(replay.out().contains("replays exactly") && replay.out().contains("Verdict: FOUND by CONTROLLER_ERROR"),
                replay.out());
    }

    @Test
    void withoutVariantsTheExperimentAsksWhichDriverFindsMoreOfTheReferencesOwnFailures(@TempDir Path dir)
            throws IOException {
        Path out = dir.resolve("out");
        CliRunner r = CliRunner.run("run", preset(dir, "").toString(), "--out", out.toString(), "--threads", "1");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        String manifest = Files.readString(out.resolve("manifest.properties"));
        assertTrue(manifest.contains("variants=none\n") && manifest.contains("primary_measure=distinct_own_failures\n"),
                manifest);
        List<String> rows = rows(out);
        List<String> header = List.of(rows.get(0).split(","));
        assertTrue(rows.stream().skip(1).allMatch(l -> l.split(",")[header.indexOf("fault")].equals("NONE")),
                "only reference rows: there is no variant");
        // the lane keeper brakes for nothing and knows no junction: it fails on its own, and each is listed
        assertTrue(Files.readAllLines(out.resolve("own-failures.csv")).size() > 1);
        // own failures per replication and driver, recounted from runs.csv over the maps both drivers of a
        // replication judged within the ticks both spent (the pair's horizon)
        String stats = Files.readString(out.resolve("stats.csv"));
        for (int rep = 0; rep < 2; rep++) {
            long horizon = Math.min(ticks(rows, header, rep, "coverage-filter", Long.MAX_VALUE)[0],
                    ticks(rows, header, rep, "random", Long.MAX_VALUE)[0]);
            long[] filter = ticks(rows, header, rep, "coverage-filter", horizon);
            long[] random = ticks(rows, header, rep, "random", horizon);
            assertTrue(filter[1] + random[1] > 0, "a test of own failures needs some: replication " + rep);
        }
        double[] means = new double[2];
        for (int rep = 0; rep < 2; rep++) {
            long horizon = Math.min(ticks(rows, header, rep, "coverage-filter", Long.MAX_VALUE)[0],
                    ticks(rows, header, rep, "random", Long.MAX_VALUE)[0]);
            means[0] += ticks(rows, header, rep, "coverage-filter", horizon)[1] / 2.0;
            means[1] += ticks(rows, header, rep, "random", horizon)[1] / 2.0;
        }
        String line = stats.lines().filter(l -> l.startsWith("measure,own_failures,coverage-filter,random,"))
                .findFirst().orElseThrow(() -> new AssertionError(stats));
        String[] cells = line.split(",", -1);
        List<String> columns = List.of(stats.lines().findFirst().orElseThrow().split(","));
        assertEquals(means[0], Double.parseDouble(cells[columns.indexOf("mean_a")]), 1e-3, line);
        assertEquals(means[1], Double.parseDouble(cells[columns.indexOf("mean_b")]), 1e-3, line);
        assertTrue(Files.readString(out.resolve("verdict.txt")).contains("distinct own failures"));
    }

    /**
     * A driver's ticks in a replication ({@code [0]}, all its maps) and how many of its maps judged whole within
     * {@code horizon} ticks had a reference run that failed ({@code [1]}).
     */
    private static long[] ticks(List<String> rows, List<String> header, int replication, String driver, long horizon) {
        long spent = 0;
        long failed = 0;
        for (String line : rows.subList(1, rows.size())) {
            String[] c = line.split(",", -1);
            if (Integer.parseInt(c[header.indexOf("replication")]) != replication
                    || !c[header.indexOf("driver")].equals(driver) || !c[header.indexOf("fault")].equals("NONE")) {
                continue;
            }
            spent += Long.parseLong(c[header.indexOf("ticks")]);
            if (spent > horizon) {
                break;
            }
            boolean accident = false;
            for (String type : List.of("clashwithobstacle", "clashwithothercar", "leaveroad", "crosscentreline", "timeout")) {
                accident |= Long.parseLong(c[header.indexOf(type)]) > 0;
            }
            failed += accident || c[header.indexOf("outcome")].startsWith("CONTROLLER") ? 1 : 0;
        }
        return new long[] {spent, failed};
    }

    @Test
    void everyDriverRunsAnExperimentOnAJavaControllerAndItsVariant(@TempDir Path dir) throws IOException {
        Path out = dir.resolve("out");
        List<String> drivers = List.of("coverage-filter", "random", "every-other", "coverage-search", "fault-search",
                "stress-search");
        Path p = dir.resolve("all.properties");
        Files.writeString(p, "master_seed=5\ncandidates=4\nreplications=1\nbudget=ticks\ndrivers=" + String.join(",", drivers)
                + "\ngrid=experiments/paper-grid.txt\ncontroller=java:test-lane-keeper\nvariants=java:test-crashes-at-20\n");
        CliRunner r = CliRunner.run("run", p.toString(), "--out", out.toString(), "--threads", "2");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        List<String> rows = rows(out);
        List<String> header = List.of(rows.get(0).split(","));
        for (String driver : drivers) {
            long judged = rows.stream().skip(1).map(l -> l.split(",", -1))
                    .filter(c -> c[header.indexOf("driver")].equals(driver) && c[header.indexOf("fault")].equals("1")
                            && c[header.indexOf("detection")].equals("FOUND")
                            && c[header.indexOf("new_accident")].equals("CONTROLLER_ERROR"))
                    .count();
            assertTrue(judged > 0, driver + " judged a map on which the variant crashed: " + String.join("\n", rows));
        }
    }

    @Test
    void simulatesSummaryCountsTheRunsWhoseControllerFailedAndReproducesWithIt() {
        CliRunner r = CliRunner.run("simulate", "--maps", "3", "--summary", "--controller", "java:test-never-answers");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        assertTrue(r.out().matches("(?s).*controller failed +3 +100\\.0%.*"), r.out());
        assertTrue(r.out().matches("(?s).*CONTROLLER_TIMEOUT +3 +100\\.0%.*"), r.out());
        assertTrue(r.out().contains("Seeds where the controller failed: 1, 2, 3"), r.out());
        assertTrue(r.out().contains("--controller 'java:test-never-answers'"), "Reproduce keeps the controller: " + r.out());
    }

    @Test
    void everyTickWhoseCommandTheWorldClampedIsCountedInRunsCsv(@TempDir Path dir) throws IOException {
        Path out = dir.resolve("out");
        Path p = dir.resolve("speeder.properties");
        Files.writeString(p, "master_seed=3\ncandidates=2\nreplications=1\nbudget=ticks\ndrivers=random\n"
                + "grid=experiments/paper-grid.txt\ncontroller=java:test-speeder\n");
        CliRunner r = CliRunner.run("run", p.toString(), "--out", out.toString(), "--threads", "1");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        List<String> rows = rows(out);
        List<String> header = List.of(rows.get(0).split(","));
        assertTrue(rows.size() > 1, "a map was judged");
        for (String line : rows.subList(1, rows.size())) {
            String[] c = line.split(",", -1);
            // it asks for 3 m a tick on every tick, and the world never gives more than 2.5
            assertEquals(c[header.indexOf("ticks")], c[header.indexOf("clamped_ticks")], line);
        }
    }

    @Test
    void theBuiltinCarsSeededFaultsAreRefusedForAnotherController(@TempDir Path dir) throws IOException {
        CliRunner r = CliRunner.run("run", preset(dir, "faults=14\n").toString(), "--out", dir.resolve("out").toString());
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("seeded faults of the builtin car") && r.err().contains("variants=none"), r.err());
        assertFalse(Files.exists(dir.resolve("out")), "nothing was written");
    }

    @Test
    void aReferenceThatFailsOnEveryMapSaysSoFirstAndExitsNonZero(@TempDir Path dir) throws IOException {
        Path out = dir.resolve("out");
        CliRunner r = CliRunner.run("run", preset(dir, "").toString(), "--out", out.toString(), "--controller",
                "java:test-never-answers");
        assertEquals(ExitCode.FAILURE, r.exitCode(), r.out());
        assertTrue(Files.readString(out.resolve("verdict.txt")).startsWith("THE REFERENCE CONTROLLER FAILED ON EVERY MAP"));
        assertTrue(r.err().contains("failed on every map"), r.err());
    }
}
