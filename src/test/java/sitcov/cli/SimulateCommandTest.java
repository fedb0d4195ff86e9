package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinRuns;
import sitcov.judge.Simulator;
import sitcov.oracle.AccidentType;
import sitcov.oracle.NearMiss;
import sitcov.render.NearMissText;
import sitcov.render.TraceWriter;

class SimulateCommandTest {
    @TempDir
    Path folder;

    @Test
    void oneRunPrintsOneLineWithBothSeedsAndTheOutcomeThenItsNearMisses() {
        CliRunner result = CliRunner.run("simulate", "--seed", "3", "--internal-seed", "100");

        assertEquals(ExitCode.OK, result.exitCode(), result.err());
        List<String> lines = result.out().lines().toList();
        // the result line, a heading and a line per measure, a heading and a line per accident type
        assertEquals(1 + 1 + NearMiss.values().length + 1 + AccidentType.values().length, lines.size(), result.out());
        assertTrue(lines.get(1).startsWith("Near misses"), result.out());
        assertTrue(result.out().startsWith("seed 3 internal 100: "), result.out());
        assertTrue(result.out().contains("TARGET_REACHED") || result.out().contains("TIMEOUT"), result.out());
        assertTrue(result.out().contains(" ticks; accidents: "), result.out());
    }

    @Test
    void theInternalSeedDefaultsToTheExternalSeed() {
        CliRunner result = CliRunner.run("simulate", "--seed", "3");

        assertEquals(ExitCode.OK, result.exitCode(), result.err());
        assertTrue(result.out().startsWith("seed 3 internal 3: "), result.out());
    }

    @Test
    void theSameCommandTwicePrintsTheSameOutput() {
        CliRunner first = CliRunner.run("simulate", "--seed", "4", "--internal-seed", "9");
        CliRunner second = CliRunner.run("simulate", "--seed", "4", "--internal-seed", "9");

        assertEquals(ExitCode.OK, first.exitCode(), first.err());
        assertEquals(first.out(), second.out());
    }

    @Test
    void pngAndTraceAreWrittenAndNamed() throws Exception {
        Path png = folder.resolve("run.png");
        Path trace = folder.resolve("run.csv");

        CliRunner result = CliRunner.run("simulate", "--seed", "3", "--internal-seed", "100",
                "--png", png.toString(), "--trace", trace.toString());

        assertEquals(ExitCode.OK, result.exitCode(), result.err());
        assertTrue(Files.size(png) > 1000);
        List<String> rows = Files.readAllLines(trace);
        assertEquals(TraceWriter.HEADER, rows.get(0));
        assertTrue(rows.size() > 1);
        assertTrue(rows.get(1).startsWith("3,100,0,"), rows.get(1));
        assertTrue(result.out().contains("Trace written to " + trace), result.out());
        assertTrue(result.out().contains("Run drawn to " + png), result.out());
    }

    /**
     * Map 1's car passes a parked car 0.47 m off: each printed least value is the trace's last value of
     * its column, and its tick the first row where the column reached it (the trace is checked
     * against the geometry in TraceWriterTest).
     */
    @Test
    void theNearMissesPrintedAreTheTracesLeastValuesAndTheTicksTheyWereReached() throws Exception {
        Path trace = folder.resolve("one.csv");
        CliRunner result = CliRunner.run("simulate", "--seed", "1", "--trace", trace.toString());
        assertEquals(ExitCode.OK, result.exitCode(), result.err());
        List<String> rows = Files.readAllLines(trace);
        List<String> header = List.of(rows.get(0).split(","));
        List<String> lines = result.out().lines().toList();
        for (NearMiss m : NearMiss.values()) {
            int column = header.indexOf(m.column());
            String least = rows.get(rows.size() - 1).split(",")[column];
            int first = 1;
            while (!rows.get(first).split(",")[column].equals(least)) {
                first++;
            }
            String tick = rows.get(first).split(",")[2];
            String name = NearMissText.name(m);
            String line = lines.stream().filter(l -> l.startsWith("  " + name + " ")).findFirst().orElseThrow();
            String shown = least.equals("inf") ? "never"
                    : m == NearMiss.POST_ENCROACHMENT ? least.replaceAll("\\.0+$", "") + " ticks at tick " + tick
                    : least + " " + NearMissText.unit(m) + " at tick " + tick;
            assertEquals(shown, line.substring(2 + name.length()).strip(), result.out());
        }
        String parked = rows.get(rows.size() - 1).split(",")[header.indexOf(NearMiss.PARKED_GAP.column())];
        assertTrue(Double.parseDouble(parked) > 0 && Double.parseDouble(parked) < 1, "map 1's near miss: " + parked);
        for (AccidentType t : AccidentType.values()) {
            String rho = rows.get(rows.size() - 1).split(",", -1)[header.indexOf(t.robustnessColumn())];
            String line = lines.stream().filter(l -> l.startsWith("  " + t.name() + " ")).findFirst().orElseThrow();
            assertTrue(line.substring(2 + t.name().length()).strip().startsWith(
                    t == AccidentType.TIMEOUT ? rho.replaceAll("\\.0+$", "") + " ticks" : rho + " m"), line);
        }
    }

    @Test
    void aLoadedSituationFileGivesTheSameResultAsItsSeed() {
        Path situation = folder.resolve("three.situation");
        assertEquals(ExitCode.OK, CliRunner.run("map", "--seed", "3", "--save", situation.toString()).exitCode());

        CliRunner loaded = CliRunner.run("simulate", "--load", situation.toString(), "--internal-seed", "100");
        CliRunner seeded = CliRunner.run("simulate", "--seed", "3", "--internal-seed", "100");

        assertEquals(ExitCode.OK, loaded.exitCode(), loaded.err());
        assertEquals(seeded.out(), loaded.out());
    }

    @Test
    void aCalibrationOfTheBuiltinCarWithPlantedFaultsIsNotCalledFaultFree() {
        CliRunner result = CliRunner.run("simulate", "--maps", "2", "--summary", "--controller", "builtin:11");

        assertEquals(ExitCode.OK, result.exitCode(), result.err());
        assertTrue(result.out().startsWith("Calibration with planted faults: 2 maps, external seeds 1..2"), result.out());
        assertTrue(result.out().contains("--controller 'builtin:11'"), result.out());
    }

    @Test
    void theCalibrationSummarisesItsRunsAndSaysHowToReproduceThem() {
        CliRunner result = CliRunner.run("simulate", "--maps", "3", "--summary");

        assertEquals(ExitCode.OK, result.exitCode(), result.err());
        assertTrue(result.out().startsWith("Fault-free calibration: 3 maps, external seeds 1..3"), result.out());
        assertTrue(result.out().lines().anyMatch(l -> l.matches("\\s*runs\\s+3")), result.out());
        assertTrue(result.out().contains("reached the Target"), result.out());
        assertTrue(result.out().contains("mean ticks"), result.out());
        for (String type : new String[] {"CLASHWITHOBSTACLE", "CLASHWITHOTHERCAR", "LEAVEROAD", "CROSSCENTRELINE"}) {
            assertTrue(result.out().contains(type), type + " missing from:\n" + result.out());
        }
        assertTrue(result.out().contains("Reproduce: experiments/sitcov simulate --maps 3 --seed 1 --summary"), result.out());
        assertFalse(result.out().contains("seed 1 internal 1:"), "--summary leaves out the per-run lines");
        assertTrue(result.err().contains("simulate: 3/3 (100%)"), result.err());
    }

    @Test
    void withoutSummaryTheCalibrationAlsoPrintsEveryRun() {
        CliRunner result = CliRunner.run("simulate", "--maps", "2", "--seed", "7");

        assertEquals(ExitCode.OK, result.exitCode(), result.err());
        assertTrue(result.out().startsWith("seed 7 internal 7: "), result.out());
        assertTrue(result.out().contains("\nseed 8 internal 8: "), result.out());
        assertTrue(result.out().contains("Reproduce: experiments/sitcov simulate --maps 2 --seed 7\n"), result.out());
    }

    @Test
    void badInputIsRefusedWithTheFix() {
        assertRefused("--maps needs a whole number from 1 to 1000000, not '-5'", "--maps", "-5");
        assertRefused("--seed needs a whole number such as 42", "--seed", "five");
        assertRefused("--internal-seed needs a whole number such as 42", "--seed", "5", "--internal-seed", "x");
        assertRefused("give either --seed S to generate a map or --load FILE", "--internal-seed", "7");
        assertRefused("(no such file); check the path", "--load", folder.resolve("nope.situation").toString());
        assertRefused("does not exist; create it first",
                "--seed", "1", "--png", folder.resolve("missing").resolve("run.png").toString());
        assertRefused("--png goes with one run, not with --maps N", "--maps", "3", "--png", "x.png");
        assertRefused("--summary goes with --maps N", "--seed", "1", "--summary");
    }

    private static void assertRefused(String fix, String... args) {
        String[] all = new String[args.length + 1];
        all[0] = "simulate";
        System.arraycopy(args, 0, all, 1, args.length);

        CliRunner result = CliRunner.run(all);

        assertEquals(ExitCode.USAGE, result.exitCode(), String.join(" ", all));
        assertTrue(result.err().startsWith("sitcov: simulate: "), result.err());
        assertTrue(result.err().contains(fix), result.err());
        assertEquals("", result.out());
    }

    @Test
    void aSituationWithoutATargetIsRefusedBeforeItIsRun() throws Exception {
        Path file = folder.resolve("no-target.situation");
        String text = sitcov.world.SituationFile.format(sitcov.world.MapGenerator.generate(1));
        java.nio.file.Files.writeString(file, text.replaceAll("(?m)^target .*\\n", ""));
        CliRunner r = CliRunner.run("simulate", "--load", file.toString());
        assertEquals(ExitCode.USAGE, r.exitCode(), r.err());
        assertTrue(r.err().contains(file + " has no 'target X Y ROAD_ID' line; a run needs a Target"), r.err());
    }

    @Test
    void thePictureAndTheTraceMayNotNameOneFile() {
        Path same = folder.resolve("out");
        CliRunner r = CliRunner.run("simulate", "--seed", "3", "--png", same.toString(), "--trace", same.toString());
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("--png and --trace both name"), r.err());
    }

    @Test
    void theGalleryDrawsEveryRunThatWentWrongAndNoOther() throws Exception {
        Path gallery = folder.resolve("gallery");
        CliRunner r = CliRunner.run("simulate", "--maps", "150", "--seed", "280", "--summary", "--gallery",
                gallery.toString());
        assertEquals(0, r.exitCode(), r.err());
        List<String> expected = new java.util.ArrayList<>();
        for (long seed = 280; seed < 430; seed++) {
            sitcov.oracle.RunResult run = BuiltinRuns.run(sitcov.world.MapGenerator.generate(seed), seed);
            if (run.hasAccident() || run.outcome() == sitcov.oracle.Outcome.TIMEOUT) {
                expected.add(Long.toString(seed));
            }
        }
        assertTrue(expected.size() >= 2, "maps 280..429 should hold runs that went wrong: " + expected);
        List<String> index = Files.readAllLines(gallery.resolve("index.csv"));
        assertEquals(expected, index.stream().skip(1).map(l -> l.split(",")[1]).toList());
        for (String row : index.subList(1, index.size())) {
            assertTrue(Files.size(gallery.resolve(row.split(",")[0])) > 0, row);
        }
        assertTrue(Files.readString(gallery.resolve("index.html")).contains("<img src=\"" + index.get(1).split(",")[0]));
        assertTrue(r.out().contains("Gallery: " + expected.size() + " runs"), r.out());
    }

    @Test
    void runsBatchedOverAControllerProgramPrintWhatRunsOneAtATimePrint() throws java.io.IOException {
        org.junit.jupiter.api.Assumptions.assumeTrue("true".equals(System.getenv("CI")) || python3Runs(),
                "python3 is not installed here: batches over a Python controller are not tested");
        Path script = folder.resolve("batched.py");
        Files.writeString(script, String.join("\n",
                "import sys",
                "sys.path.insert(0, 'experiments/controllers')",
                "from sitcov_client import serve",
                "def step(o):",
                "    ch = o['channels']",
                "    speed = min(1.5, ch['target_distance'] / 3.0)",
                "    if ch['distance_to_junction'] is not None:",
                "        speed = min(speed, max(0.0, (ch['distance_to_junction'] - 2.0) / 4.0))",
                "    return {'speed': speed, 'steering': -(ch['heading_error'] or 0.0) - 5 * (ch['lane_offset'] or 0.0)}",
                "serve(step_batch=lambda obs: [step(o) for o in obs], name='batched', channels=['lane_offset',"
                        + " 'heading_error', 'distance_to_junction', 'target_distance'], sensors=[], batch=4)",
                ""));
        String controller = "exec:python3 " + script;
        CliRunner one = CliRunner.run("simulate", "--maps", "5", "--controller", controller);
        CliRunner four = CliRunner.run("simulate", "--maps", "5", "--controller", controller, "--batch", "4");
        assertEquals(ExitCode.OK, one.exitCode(), one.err());
        assertEquals(ExitCode.OK, four.exitCode(), four.err());
        assertEquals(one.out(), four.out());
        assertFalse(four.out().contains("CONTROLLER_ERROR"), four.out());
        assertTrue(four.out().contains("seed 5 internal 5"), four.out());
        assertFalse(four.err().contains("batches of"), four.err());
    }

    @Test
    void batchesGoWithManyMapsAndAControllerProgram() {
        CliRunner builtin = CliRunner.run("simulate", "--maps", "2", "--batch", "4");
        assertEquals(ExitCode.USAGE, builtin.exitCode());
        assertTrue(builtin.err().contains("--batch B goes with --controller exec:COMMAND"), builtin.err());
        CliRunner one = CliRunner.run("simulate", "--seed", "2", "--batch", "4");
        assertEquals(ExitCode.USAGE, one.exitCode());
        assertTrue(one.err().contains("--batch B goes with --maps N"), one.err());
    }

    private static boolean python3Runs() {
        try {
            return new ProcessBuilder("python3", "--version").start().waitFor() == 0;
        } catch (java.io.IOException | InterruptedException e) {
            return false;
        }
    }
}
