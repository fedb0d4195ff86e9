package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinCar;
import sitcov.drivers.Drivers;
import sitcov.experiment.CampaignConfig;
import sitcov.experiment.CampaignTarget;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ExperimentEvent;
import sitcov.experiment.ExperimentRunner;
import sitcov.experiment.Shard;
import sitcov.faults.Fault;
import sitcov.report.ResultsRecorder;
import sitcov.results.CampaignManifest;
import sitcov.results.Manifest;

class CampaignRunTest {
    private static final String TINY = "src/test/resources/presets/campaign-tiny.properties";
    private static final long BUDGET = 10_000;
    private static Path reference;

    @TempDir
    Path dir;

    /** The tiny campaign run once, on 2 threads, shared by the tests that only read it. */
    private static synchronized Path reference() throws IOException {
        if (reference == null) {
            Path folder = Files.createTempDirectory("campaign-reference").resolve("run");
            CliRunner r = CliRunner.run("run", TINY, "--out", folder.toString(), "--threads", "2");
            assertEquals(0, r.exitCode(), r.err());
            assertTrue(r.out().contains("Verdict"), "run prints the campaign's verdict: " + r.out());
            reference = folder;
        }
        return reference;
    }

    @Test
    void eachTrialIsFalsifiedAtItsFirstFoundMapWithTheTicksItsRunsCostUpToThere() throws IOException {
        Path folder = reference();
        List<Map<String, String>> trials = rows(folder.resolve("campaign.csv"));
        assertEquals(2 * 2 * 2, trials.size(), "faults × drivers × trials");
        int falsified = 0;
        int censored = 0;
        for (Map<String, String> t : trials) {
            String sub = String.format("fault-%02d", Integer.parseInt(t.get("fault")));
            // the trial's map blocks in runs.csv, in order: the fault-free row of each map, then its faulty row
            long sum = 0;
            long toFailure = -1;
            int maps = 0;
            int foundAt = -1;
            for (Map<String, String> run : rows(folder.resolve(sub).resolve("runs.csv"))) {
                if (!run.get("replication").equals(t.get("trial")) || !run.get("driver").equals(t.get("driver"))) {
                    continue;
                }
                sum += Long.parseLong(run.get("ticks"));
                if (!run.get("fault").equals("NONE")) {
                    maps++;
                    if (run.get("detection").equals("FOUND") && toFailure < 0) {
                        toFailure = sum;
                        foundAt = Integer.parseInt(run.get("map_index"));
                    }
                }
            }
            boolean within = toFailure >= 0 && toFailure <= BUDGET;
            assertEquals(Boolean.toString(within), t.get("falsified"), "falsified " + t);
            assertEquals(Long.toString(toFailure >= 0 ? toFailure : sum), t.get("ticks_to_failure"), "ticks " + t);
            assertEquals(Long.toString(within ? toFailure : Math.min(sum, BUDGET)), t.get("survival_ticks"), "time " + t);
            assertEquals(Integer.toString(maps), t.get("maps_run"));
            if (toFailure >= 0) {
                // the trial stopped at the map that found its fault: nothing ran after it
                assertEquals(maps - 1, foundAt, "the found map is the trial's last " + t);
                assertEquals("falsified", t.get("stopped_by"));
            } else {
                assertTrue(sum >= BUDGET, "an unfalsified trial spent its budget: " + t);
            }
            falsified += within ? 1 : 0;
            censored += within ? 0 : 1;
        }
        assertTrue(falsified > 0 && censored > 0, "the tiny campaign has a fault found within the budget and one not");
        assertTrue(trials.stream().filter(t -> t.get("fault").equals("17")).allMatch(t -> t.get("falsified").equals("true")),
                "fault 17 is falsified in every trial (the preset's comment)");
        assertTrue(trials.stream().filter(t -> t.get("fault").equals("8")).noneMatch(t -> t.get("falsified").equals("true")),
                "fault 8 in none");
    }

    @Test
    void theSurvivalStatisticsAreComputedFromTheTrialsAndTheStratifiedTestSumsTheFaults() throws IOException {
        Path folder = reference();
        List<Map<String, String>> trials = rows(folder.resolve("campaign.csv"));
        for (Map<String, String> d : rows(folder.resolve("campaign-drivers.csv"))) {
            List<Long> failures = new ArrayList<>();
            for (Map<String, String> t : trials) {
                if (t.get("fault").equals(d.get("fault")) && t.get("driver").equals(d.get("driver"))
                        && t.get("falsified").equals("true")) {
                    failures.add(Long.parseLong(t.get("survival_ticks")));
                }
            }
            failures.sort(null);
            assertEquals(Integer.toString(failures.size()), d.get("falsified"));
            // with 2 trials and none censored before the budget, the curve first reaches 0.5 at the earliest
            // failure: that is the median, or it is not reached when neither trial failed
            assertTrue(trials.stream().filter(t -> t.get("falsified").equals("false"))
                    .allMatch(t -> t.get("survival_ticks").equals(Long.toString(BUDGET))), "censored at the budget");
            String median = failures.isEmpty() ? "not reached" : Long.toString(failures.get(0));
            assertEquals(median, d.get("km_median_ticks"), "median of " + d);
        }
        double o = 0;
        double e = 0;
        double v = 0;
        Map<String, String> all = null;
        for (Map<String, String> s : rows(folder.resolve("campaign-stats.csv"))) {
            if (s.get("fault").equals("ALL")) {
                all = s;
                continue;
            }
            // the log-rank test's observed events of the first driver are its falsified trials
            assertEquals(Double.parseDouble(s.get("falsified_a")), Double.parseDouble(s.get("logrank_observed_a")), 1e-12);
            o += Double.parseDouble(s.get("logrank_observed_a"));
            e += Double.parseDouble(s.get("logrank_expected_a"));
            v += Double.parseDouble(s.get("logrank_variance"));
        }
        assertTrue(all != null, "a stratified row");
        assertEquals(o, Double.parseDouble(all.get("logrank_observed_a")), 1e-4);
        assertEquals(e, Double.parseDouble(all.get("logrank_expected_a")), 1e-4);
        assertEquals(v, Double.parseDouble(all.get("logrank_variance")), 1e-4);
    }

    @Test
    void oneThreadWritesTheSameBytesAsTwoAndReportWritesThemAgain() throws IOException {
        Path one = dir.resolve("one");
        CliRunner r = CliRunner.run("run", TINY, "--out", one.toString(), "--threads", "1");
        assertEquals(0, r.exitCode(), r.err());
        assertSame(reference(), one);
        CliRunner again = CliRunner.run("report", one.toString());
        assertEquals(0, again.exitCode(), again.err());
        assertSame(reference(), one);
    }

    /** Starts the campaign's trials of {@code fault} into its sub-folder as run does, stopped as a kill would after {@code maps} maps. */
    private static void killed(CampaignConfig campaign, Path folder, CampaignTarget fault, int maps) throws Exception {
        ExperimentConfig config = campaign.trialsOf(fault);
        ResultsRecorder recorder = ResultsRecorder.create(folder.resolve(fault.folder()),
                new Manifest(config, Version.current(), Shard.WHOLE, false, false), Map.of(), System::nanoTime, BuiltinCar.FACTORY);
        ExperimentRunner[] runner = new ExperimentRunner[1];
        int[] judged = {0};
        runner[0] = new ExperimentRunner(config, Drivers.standard(), Shard.WHOLE, recorder.journal(), 2, System::nanoTime,
                List.of(recorder, ev -> {
                    if (ev instanceof ExperimentEvent.MapJudged && ++judged[0] == maps) {
                        runner[0].halt();
                    }
                }), BuiltinCar.SOURCE);
        assertFalse(runner[0].run(), "the run was meant to stop after " + maps + " maps");
        recorder.close();
    }

    @Test
    void aCampaignKilledInTheMiddleOfAFaultResumesToTheSameBytes() throws Exception {
        CampaignConfig campaign = Preset.read(Path.of(TINY), null, Drivers.standard()).campaign();
        // killed in its first fault (8, never found), and killed in its last (17, found within a few maps: the
        // resumed trials replay the map that falsified them and must stop there again)
        for (int f = 0; f < 2; f++) {
            Path folder = dir.resolve("killed-" + f);
            Files.createDirectories(folder);
            new CampaignManifest(campaign, Version.current(), false).write(folder);
            for (int before = 0; before < f; before++) {
                String sub = campaign.targets().get(before).folder();
                ResultsFolders.copy(reference().resolve(sub), folder.resolve(sub));
            }
            killed(campaign, folder, campaign.targets().get(f), f == 0 ? 5 : 3);
            // a kill while the campaign's own files were written whole leaves a temporary copy: resume sweeps it
            Files.writeString(folder.resolve(".campaign.csv77.tmp"), "fault,driv");
            CliRunner r = CliRunner.run("run", "--resume", folder.toString(), "--threads", "2");
            assertEquals(0, r.exitCode(), r.err());
            assertSame(reference(), folder);
        }
    }

    @Test
    void aCampaignFolderWhoseManifestNoLongerMatchesItsFaultsIsNotReported() throws IOException {
        Path folder = dir.resolve("edited");
        ResultsFolders.copy(reference(), folder);
        Path manifest = folder.resolve(CampaignManifest.FILE);
        Files.writeString(manifest, Files.readString(manifest).replace("tick_budget=10000", "tick_budget=20000"));
        byte[] before = Files.readAllBytes(folder.resolve("campaign.csv"));
        CliRunner r = CliRunner.run("report", folder.toString());
        assertEquals(ExitCode.USAGE, r.exitCode(), r.err());
        assertTrue(r.err().contains("holds another experiment than this campaign's trials of fault 8"), r.err());
        assertArrayEquals(before, Files.readAllBytes(folder.resolve("campaign.csv")), "nothing was rewritten");
    }

    @Test
    void presetsThatMixTheProtocolsAreRefusedWithOneMessageNamingTheFix() throws IOException {
        String base = "master_seed=1\ndrivers=random\nfaults=17\n";
        Map<String, String> cases = Map.of(
                "protocol=campaign\ntrials=2\n", "needs tick_budget=",
                "candidates=10\ntick_budget=100\n", "add protocol=campaign",
                "protocol=campaign\ntrials=2\ntick_budget=100\ncandidates=5\n", "remove candidates=",
                "protocol=campaign\ntrials=2\ntick_budget=100\nbudget=ticks\n", "remove budget=",
                "protocol=campaigns\ncandidates=10\n", "protocol=campaign (falsification campaigns)",
                "protocol=campaign\ntrials=2\ntick_budget=0\n", "tick_budget= needs a whole number from 1");
        for (Map.Entry<String, String> c : cases.entrySet()) {
            Path preset = dir.resolve("bad-" + Math.abs(c.getKey().hashCode()) + ".properties");
            Files.writeString(preset, base + c.getKey());
            Path out = dir.resolve("out-" + Math.abs(c.getKey().hashCode()));
            CliRunner r = CliRunner.run("run", preset.toString(), "--out", out.toString());
            assertEquals(ExitCode.USAGE, r.exitCode(), c.getKey() + r.err());
            assertTrue(r.err().contains(c.getValue()), "the message names the fix for " + c.getKey() + ": " + r.err());
            assertFalse(r.err().contains("\tat "), "no stack trace: " + r.err());
            assertFalse(Files.exists(out), "nothing was written for " + c.getKey());
        }
    }

    /** The rows of a CSV file without quoted fields, by column name. */
    private static List<Map<String, String>> rows(Path csv) throws IOException {
        List<String> lines = Files.readAllLines(csv);
        String[] header = lines.get(0).split(",", -1);
        List<Map<String, String>> rows = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            String[] cells = line.split(",", -1);
            Map<String, String> row = new HashMap<>();
            for (int i = 0; i < header.length; i++) {
                row.put(header[i], cells[i]);
            }
            rows.add(row);
        }
        return rows;
    }

    /** Every result file of the two campaign folders, sub-folders included, is the same byte for byte. */
    private static void assertSame(Path expected, Path actual) throws IOException {
        assertTrue(ResultsFolders.campaignFiles(expected).contains("fault-17/runs.csv"), "a campaign folder of fault 17");
        ResultsFolders.assertSameCampaign(expected, actual);
    }
}
