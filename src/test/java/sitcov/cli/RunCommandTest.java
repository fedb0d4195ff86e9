package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.drivers.Drivers;
import sitcov.experiment.Candidate;
import sitcov.results.ResultsFolder;

class RunCommandTest {
    @TempDir
    Path dir;

    @Test
    void theTinyPresetGivesByteIdenticalResultsWithOneAndTwoThreads() throws Exception {
        Path one = dir.resolve("one");
        CliRunner a = CliRunner.run("run", ResultsFolders.TINY, "--threads", "1", "--out", one.toString());
        assertEquals(0, a.exitCode(), a.err());
        ResultsFolders.assertSameResults(ResultsFolders.tinyReference(), one);
        for (String file : List.of(ResultsFolder.RUNS, ResultsFolder.DRIVERS, ResultsFolder.SUMMARY, ResultsFolder.TABLE2,
                ResultsFolder.COVERAGE_CURVE, ResultsFolder.FIG2, ResultsFolder.FIG3, ResultsFolder.FIG3_TIME,
                ResultsFolder.TIMINGS, ResultsFolder.EXECUTION, ResultsFolder.GRID, ResultsFolder.MANIFEST)) {
            assertTrue(Files.size(one.resolve(file)) > 0, file);
        }
        String manifest = Files.readString(one.resolve(ResultsFolder.MANIFEST));
        assertTrue(manifest.contains("\nbudget=ticks\n") && manifest.contains("\ncomplete=true\n"), manifest);
        assertTrue(manifest.contains("\nfaulty_runs=until-verdict\n"), "the default is recorded: " + manifest);
        assertTrue(manifest.contains("\ndrivers=coverage-filter,random\n"), manifest);
        assertTrue(a.out().contains("Results in " + one), a.out());
        List<String> lines = a.out().lines().toList();
        assertEquals("The report: " + one.resolve(ResultsFolder.REPORT)
                + " (the verdict, every table and figure on one page; open it in a browser)", lines.get(lines.size() - 1),
                "the last line names the report: " + a.out());
    }

    @Test
    void aThirdDriverNeedsOnlyItsNameInThePreset() throws Exception {
        Path out = dir.resolve("three");
        CliRunner r = CliRunner.run("run", "src/test/resources/presets/three-drivers.properties", "--out", out.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().contains("every-other     differential"), r.out());
        List<String> drivers = Files.readAllLines(out.resolve(ResultsFolder.DRIVERS));
        assertEquals(1 + 2 * 3, drivers.size(), "a row per driver and replication: " + drivers);
        assertTrue(drivers.get(3).startsWith("0,every-other,"), drivers.get(3));
        String table2 = Files.readAllLines(out.resolve(ResultsFolder.TABLE2)).get(0);
        assertEquals("fault,name,notion,coverage-filter,random,every-other,coverage-filter_minus_random,"
                + "coverage-filter_minus_every-other,random_minus_every-other", table2);
        long everyOtherRows = Files.readAllLines(out.resolve(ResultsFolder.SUMMARY)).stream()
                .filter(l -> l.startsWith("every-other,")).count();
        assertEquals(2 * 2, everyOtherRows, "two replications under two notions");
        Set<String> drawn = new HashSet<>();
        for (String line : Files.readAllLines(out.resolve(ResultsFolder.RUNS))) {
            if (line.contains(",every-other,")) {
                drawn.add(line.split(",")[3]);
            }
        }
        assertTrue(drawn.size() > 3 && drawn.stream().allMatch(c -> Integer.parseInt(c) % 2 == 0), drawn.toString());
    }

    @Test
    void aSweepPresetGoesThroughRunToSweepCsvAndFigureFour() throws Exception {
        Path out = dir.resolve("sweep");
        CliRunner r = CliRunner.run("run", "src/test/resources/presets/tiny-sweep.properties", "--out", out.toString());
        assertEquals(0, r.exitCode(), r.err());
        List<String> sweep = Files.readAllLines(out.resolve(ResultsFolder.SWEEP));
        assertEquals(1 + 4, sweep.size(), sweep.toString());
        assertTrue(Files.size(out.resolve(ResultsFolder.FIG4)) > 0);
        List<String> runs = Files.readAllLines(out.resolve(ResultsFolder.RUNS));
        for (int i = 1; i < sweep.size(); i++) {
            String[] point = sweep.get(i).split(",");
            int replication = i - 1;
            assertEquals(i <= 2 ? "5" : "10", point[0], "budget of map set " + point[1]);
            // cells covered, recomputed from runs.csv: distinct cells of that replication's fault-free rows
            long cells = runs.stream().skip(1).map(l -> l.split(","))
                    .filter(f -> f[0].equals(Integer.toString(replication)) && f[11].equals("NONE"))
                    .map(f -> f[7]).distinct().count();
            assertEquals(cells, Long.parseLong(point[4]), sweep.get(i));
        }
        assertTrue(r.out().contains("4 map sets"), r.out());
    }

    @Test
    void resultsNeverOverwriteAFolderThatHasFiles() throws Exception {
        Files.writeString(dir.resolve("keep.txt"), "mine");
        CliRunner r = CliRunner.run("run", ResultsFolders.TINY, "--out", dir.toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("not an empty folder"), r.err());
        assertEquals("mine", Files.readString(dir.resolve("keep.txt")));
    }

    @Test
    void anUnknownPresetNamesWhereThePresetsAre() {
        CliRunner r = CliRunner.run("run", "no-such-preset");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("experiments/"), r.err());
    }

    @Test
    void presetMistakesAreRefusedNamingTheFix() throws Exception {
        String[][] cases = {
            {"drivers=coverage-filter,best", "unknown driver 'best'; the drivers are coverage-filter, random, every-other"},
            {"drivers=random,random", "each once"},
            {"candidates=many", "candidates= needs a whole number from 1 to 10000000, not 'many'"},
            {"colour=blue", "unknown key 'colour'"},
            {"sweep=5,-1", "sweep= needs positive candidate counts"},
            {"candidate_limit=3", "candidate_limit 3 is below the first driver's 12 candidates"},
            {"budget=money", "unknown budget 'money'; use wall-clock or ticks"},
            {"faulty_runs=sometimes", "unknown faulty_runs 'sometimes'; use until-verdict or to-end"},
            {"primary_measure=speed", "primary_measure= unknown measure 'speed'; the measures are [cells_covered,"},
            {"primary_drivers=random,best", "primary_drivers= names 'best', which is not one of the drivers"},
            {"primary_drivers=random,random", "primary_drivers names two different drivers"},
            {"primary_direction=up", "unknown primary_direction 'up'; use two-sided, higher or lower"},
            {"margin_faults_found=one", "margin_faults_found= needs a positive number such as 1.0, not 'one'"},
            {"margin_discovery_area=-0.1", "margin_discovery_area must be a positive number"},
        };
        String base = Files.readString(Path.of(ResultsFolders.TINY));
        for (String[] c : cases) {
            String key = c[0].substring(0, c[0].indexOf('='));
            Path preset = dir.resolve("bad.properties");
            Files.writeString(preset, base.replaceAll("(?m)^" + key + "=.*$", "") + "\n" + c[0] + "\n");
            CliRunner r = CliRunner.run("run", preset.toString(), "--out", dir.resolve("never").toString());
            assertEquals(2, r.exitCode(), c[0] + ": " + r.err());
            assertTrue(r.err().contains(c[1]), c[0] + ": " + r.err());
            assertTrue(!Files.exists(dir.resolve("never")), c[0] + " left a results folder behind");
        }
    }

    @Test
    void aBadShardIsRefused() {
        for (String shard : new String[] {"0/3", "4/3", "1/0", "two"}) {
            CliRunner r = CliRunner.run("run", ResultsFolders.TINY, "--shard", shard, "--out", dir.resolve("x").toString());
            assertEquals(2, r.exitCode(), shard);
            assertTrue(r.err().contains("a shard is K/N"), r.err());
        }
    }

    @Test
    void moreShardsThanReplicationsAreRefusedAtOnceNamingTheLimit() {
        // tiny has 3 replications: a fourth shard would hold none, so it would have nothing to compare or merge
        Path out = dir.resolve("x");
        CliRunner r = CliRunner.run("run", ResultsFolders.TINY, "--shard", "4/4", "--out", out.toString());
        assertEquals(2, r.exitCode(), r.err());
        assertTrue(r.err().contains("run: --shard 4/4: tiny has 3 replications, so no more than 3 shards (each needs one);"
                + " use --shard K/3, or run more with --replications N."), r.err());
        assertFalse(Files.exists(out), "refused before anything was written");
        CliRunner sweep = CliRunner.run("run", "src/test/resources/presets/tiny-sweep.properties", "--shard", "1/5",
                "--out", out.toString());
        assertEquals(2, sweep.exitCode(), sweep.err());
        assertTrue(sweep.err().contains("has 4 map sets, so no more than 4 shards"), sweep.err());
    }

    @Test
    void runAgainRunsAFoldersExperimentShardAndAllIntoANewFolderAndTakesNothingThatWouldChangeIt() throws Exception {
        Path shard = dir.resolve("shard-2");
        CliRunner first = CliRunner.run("run", ResultsFolders.TINY, "--shard", "2/3", "--out", shard.toString());
        assertEquals(0, first.exitCode(), first.err());
        Path again = dir.resolve("again");
        CliRunner r = CliRunner.run("run", "--again", shard.toString(), "--out", again.toString(), "--threads", "1");
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.err().contains("run: tiny shard 2/3: 1 replications"), r.err());
        ResultsFolders.assertSameResults(shard, again);
        Path never = dir.resolve("never");
        for (String option : new String[] {"--seed", "--replications", "--shard", "--controller"}) {
            CliRunner refused = CliRunner.run("run", "--again", shard.toString(), option, "1/3", "--out", never.toString());
            assertEquals(ExitCode.USAGE, refused.exitCode(), option + ": " + refused.err());
            assertTrue(refused.err().contains("--again DIR takes the experiment from DIR's manifest; give only --out,"
                    + " --threads, --record, --fork and --dry-run beside it."), refused.err());
        }
        CliRunner none = CliRunner.run("run", "--again", dir.toString(), "--out", never.toString());
        assertEquals(ExitCode.USAGE, none.exitCode(), none.err());
        assertTrue(none.err().contains("--again " + dir + " is not a results folder (it has no manifest.properties)"),
                none.err());
        assertFalse(Files.exists(never), "nothing was written for a refused command");
    }

    @Test
    void aDryRunChecksThePresetAndTheShardAndWritesNothing() {
        Path out = dir.resolve("never");
        CliRunner ok = CliRunner.run("run", ResultsFolders.TINY, "--shard", "3/3", "--dry-run", "--out", out.toString(),
                "--threads", "1");
        assertEquals(0, ok.exitCode(), ok.err());
        assertTrue(ok.out().startsWith("run: tiny shard 3/3: 1 replications, drivers coverage-filter, random, budget ticks,"
                + " on 1 threads: sound; a dry run"), ok.out());
        assertFalse(Files.exists(out));
        CliRunner bad = CliRunner.run("run", ResultsFolders.TINY, "--shard", "4/4", "--dry-run");
        assertEquals(2, bad.exitCode());
        assertTrue(bad.err().contains("no more than 3 shards"), bad.err());
        assertEquals(2, CliRunner.run("run", "--resume", dir.toString(), "--dry-run").exitCode());
    }

    @Test
    void aResultsFolderDeletedWhileTheRunWritesStopsItWithOneMessageAndNoTrace() throws Exception {
        Path out = dir.resolve("doomed");
        // a driver that deletes the folder after its first judged map, as an 'rm -r' beside the run would
        Drivers drivers = Drivers.standard().with("deleting", () -> session -> {
            int judged = 0;
            while (session.budgetLeft()) {
                Candidate c = session.nextCandidate();
                if (c.runnable()) {
                    session.run(c);
                    if (judged++ == 0) {
                        deleteTree(out);
                    }
                }
            }
        });
        Path preset = dir.resolve("doomed.properties");
        Files.writeString(preset, "master_seed=3\ncandidates=6\nfaults=19\ndrivers=deleting\n"
                + "grid=experiments/paper-grid.txt\n");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = new Main(List.of(new RunCommand(drivers))).execute(new String[] {"run", preset.toString(), "--out",
                out.toString(), "--threads", "1"}, new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        String message = err.toString(StandardCharsets.UTF_8);
        assertEquals(ExitCode.FAILURE, code, message);
        assertTrue(message.contains("sitcov: run: the results folder " + out + " was deleted (or its .sitcov.lock removed)"
                + " while this command wrote into it; it stopped there"), message);
        assertFalse(message.contains("Exception") || message.contains("\tat "), message);
        assertFalse(Files.exists(out), "nothing made the folder again");
    }

    private static void deleteTree(Path folder) {
        try (Stream<Path> files = Files.walk(folder)) {
            for (Path f : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(f);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
