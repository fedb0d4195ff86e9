package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
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

    @TempDir
    Path dir;

    /** The tiny campaign run once, shared by the tests that only read it. */
    static Path reference() throws IOException {
        return ResultsFolders.ranOnce(TINY);
    }

    @Test
    void eachTrialIsFalsifiedAtItsFirstFoundMapWithTheTicksItsRunsCostUpToThere() throws IOException {
        Path folder = reference();
        List<Map<String, String>> trials = ResultsFolders.csvRows(folder.resolve("campaign.csv"));
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
            for (Map<String, String> run : ResultsFolders.csvRows(folder.resolve(sub).resolve("runs.csv"))) {
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
        List<Map<String, String>> trials = ResultsFolders.csvRows(folder.resolve("campaign.csv"));
        for (Map<String, String> d : ResultsFolders.csvRows(folder.resolve("campaign-drivers.csv"))) {
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
        for (Map<String, String> s : ResultsFolders.csvRows(folder.resolve("campaign-stats.csv"))) {
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

    @Test
    void aFolderThatKeepsOnlyCampaignCsvHasEveryOtherFileWrittenAgainFromItsTrials() throws IOException {
        Path kept = dir.resolve("kept");
        ResultsFolders.copyCampaignTrials(reference(), kept);
        CliRunner r = CliRunner.run("report", kept.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().contains("keeps campaign.csv but not its sub-folders"), r.out());
        ResultsFolders.assertSameCampaignFiles(reference(), kept);
    }

    @Test
    void aCampaignCsvChangedByHandIsRefusedByItsDigestAndNothingIsWritten() throws IOException {
        Path kept = dir.resolve("kept");
        ResultsFolders.copyCampaignTrials(reference(), kept);
        assertTrue(Files.readString(kept.resolve("campaign.properties")).contains("trials_sha256="), "a digest kept");
        Path trials = kept.resolve("campaign.csv");
        // a plausible edit: one more tick to a trial's failure, which no row's form betrays
        List<String> lines = new java.util.ArrayList<>(Files.readAllLines(trials));
        String[] cells = lines.get(3).split(",", -1);
        cells[6] = Long.toString(Long.parseLong(cells[6]) + 1);
        lines.set(3, String.join(",", cells));
        Files.write(trials, lines);
        byte[] before = Files.readAllBytes(trials);
        CliRunner r = CliRunner.run("report", kept.toString());
        assertEquals(ExitCode.USAGE, r.exitCode(), r.err());
        assertTrue(r.err().contains("campaign.csv was changed after sitcov wrote it (it does not match trials_sha256"), r.err());
        assertFalse(r.err().contains("\tat "), "no stack trace: " + r.err());
        assertArrayEquals(before, Files.readAllBytes(trials));
        assertFalse(Files.exists(kept.resolve("verdict.txt")), "no verdict written from a changed campaign.csv");
    }

    @Test
    void aCampaignCsvWrittenBeforeItsDigestIsReportedWithAWarningAndAMalformedRowIsRefusedByNumber() throws Exception {
        CampaignConfig campaign = Preset.read(Path.of(TINY), null, Drivers.standard()).campaign();
        Path kept = dir.resolve("kept");
        ResultsFolders.copyCampaignTrials(reference(), kept);
        new CampaignManifest(campaign, Version.current(), true).write(kept);
        CliRunner r = CliRunner.run("report", kept.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.err().contains("campaign.csv was written before sitcov kept its digest"), r.err());
        assertFalse(Files.readString(kept.resolve("campaign.properties")).contains("trials_sha256="),
                "trials read back unattested are not attested by report");
        Path trials = kept.resolve("campaign.csv");
        List<String> lines = new java.util.ArrayList<>(Files.readAllLines(trials));
        String[] cells = lines.get(3).split(",", -1);
        cells[6] = "many";
        lines.set(3, String.join(",", cells));
        Files.write(trials, lines);
        CliRunner bad = CliRunner.run("report", kept.toString());
        assertEquals(ExitCode.USAGE, bad.exitCode(), bad.err());
        assertTrue(bad.err().contains("campaign.csv, row 4, is not a trial this campaign wrote"), bad.err());
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
        String written = Files.readString(manifest);
        byte[] before = Files.readAllBytes(folder.resolve("campaign.csv"));
        Files.writeString(manifest, written.replace("tick_budget=10000", "tick_budget=20000"));
        CliRunner r = CliRunner.run("report", folder.toString());
        assertEquals(ExitCode.USAGE, r.exitCode(), r.err());
        assertTrue(r.err().contains(manifest + ": tick_budget was changed after sitcov wrote it"), r.err());
        // a campaign written before its manifest was checked: its sub-folders' manifests still refuse the edit
        Files.writeString(manifest, written.replaceAll("(?m)^checks=.*\n", "").replace("tick_budget=10000",
                "tick_budget=20000"));
        CliRunner unchecked = CliRunner.run("report", folder.toString());
        assertEquals(ExitCode.USAGE, unchecked.exitCode(), unchecked.err());
        assertTrue(unchecked.err().contains("holds another experiment than this campaign's trials of fault 8"), unchecked.err());
        assertTrue(unchecked.err().contains(manifest + " was written before sitcov checked it"), unchecked.err());
        assertArrayEquals(before, Files.readAllBytes(folder.resolve("campaign.csv")), "nothing was rewritten");
    }

    @Test
    void aFaultDroppedFromTheCampaignsManifestIsRefusedByReportAndByResume() throws IOException {
        Path folder = dir.resolve("dropped");
        ResultsFolders.copy(reference(), folder);
        Path manifest = folder.resolve(CampaignManifest.FILE);
        String written = Files.readString(manifest);
        assertTrue(written.contains("\nfaults=8,17\n") && written.contains("\nchecks="), written);
        byte[] verdict = Files.readAllBytes(folder.resolve("verdict.txt"));
        Files.writeString(manifest, written.replace("\nfaults=8,17\n", "\nfaults=17\n"));
        CliRunner report = CliRunner.run("report", folder.toString());
        assertEquals(ExitCode.USAGE, report.exitCode(), report.err());
        assertTrue(report.err().contains(manifest + ": faults was changed after sitcov wrote it"), report.err());
        assertArrayEquals(verdict, Files.readAllBytes(folder.resolve("verdict.txt")), "the verdict keeps fault 8");

        // left incomplete (complete= is the one line the tool flips), resume must not mark it complete without fault 8
        String incomplete = written.replace("\ncomplete=true\n", "\ncomplete=false\n");
        Files.writeString(manifest, incomplete.replace("\nfaults=8,17\n", "\nfaults=17\n"));
        CliRunner resume = CliRunner.run("run", "--resume", folder.toString(), "--threads", "1");
        assertEquals(ExitCode.USAGE, resume.exitCode(), resume.err());
        assertTrue(resume.err().contains("faults was changed after sitcov wrote it"), resume.err());
        assertTrue(Files.readString(manifest).contains("\ncomplete=false\n"), "still incomplete");

        // one written before campaigns were checked: the sub-folder of the fault it no longer lists gives it away
        Files.writeString(manifest, incomplete.replaceAll("(?m)^checks=.*\n", "").replace("\nfaults=8,17\n",
                "\nfaults=17\n"));
        for (List<String> args : List.of(List.of("report", folder.toString()),
                List.of("run", "--resume", folder.toString(), "--threads", "1"))) {
            CliRunner r = CliRunner.run(args.toArray(String[]::new));
            assertEquals(ExitCode.USAGE, r.exitCode(), args + ": " + r.err());
            assertTrue(r.err().contains(manifest + " lists no target of " + folder.resolve("fault-08")), r.err());
        }
        assertTrue(Files.readString(manifest).contains("\ncomplete=false\n"), "still incomplete");
        assertArrayEquals(verdict, Files.readAllBytes(folder.resolve("verdict.txt")), "nothing was rewritten");
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

    /** Every result file of the two campaign folders, sub-folders included, is the same byte for byte. */
    static void assertSame(Path expected, Path actual) throws IOException {
        assertTrue(ResultsFolders.campaignFiles(expected).contains("fault-17/runs.csv"), "a campaign folder of fault 17");
        ResultsFolders.assertSameCampaign(expected, actual);
    }
}
