package sitcov.cli;

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

/** Campaigns of the reference's own requirements, on the tiny preset whose comment says what it falsifies. */
class RequirementCampaignTest {
    private static final String TINY = "src/test/resources/presets/requirement-tiny.properties";
    private static final long BUDGET = 12_000;

    @TempDir
    Path dir;

    /** The tiny campaign run once, shared by the tests that only read it. */
    static Path reference() throws IOException {
        return ResultsFolders.ranOnce(TINY);
    }

    @Test
    void aTrialStopsAtTheFirstMapOnWhichTheCarMissesTheTargetAndSimulateShowsItMissIt() throws IOException {
        Path folder = reference();
        List<Map<String, String>> trials = ResultsFolders.csvRows(folder.resolve("campaign.csv"));
        assertEquals(2 * 2 * 2, trials.size(), "requirements × drivers × trials");
        int falsified = 0;
        for (Map<String, String> t : trials) {
            if (!t.get("requirement").equals("timeout") || !t.get("falsified").equals("true")) {
                continue;
            }
            falsified++;
            // the trial's maps in its sub-folder's runs.csv: their ticks sum to the ticks to failure, and the last is the found map
            long sum = 0;
            Map<String, String> last = null;
            for (Map<String, String> run : ResultsFolders.csvRows(folder.resolve("requirement-timeout/runs.csv"))) {
                if (run.get("replication").equals(t.get("trial")) && run.get("driver").equals(t.get("driver"))) {
                    sum += Long.parseLong(run.get("ticks"));
                    last = run;
                }
            }
            assertEquals(Long.parseLong(t.get("ticks_to_failure")), sum, "ticks " + t);
            assertTrue(sum <= BUDGET, "within the budget " + t);
            assertEquals(t.get("found_map"), last.get("map"), "the found map is the trial's last " + t);
            assertEquals("falsified", t.get("stopped_by"));
            // run again from its seeds by another command, the found map's run misses the Target
            String map = t.get("found_map");
            List<String> args = new ArrayList<>(List.of("simulate", "--internal-seed", t.get("found_internal_seed")));
            args.addAll(map.startsWith("seed:") ? List.of("--seed", t.get("found_external_seed"))
                    : List.of("--load", folder.resolve("requirement-timeout/situations/" + map.substring("situation:".length())
                    + ".situation").toString()));
            CliRunner replay = CliRunner.run(args.toArray(String[]::new));
            assertEquals(0, replay.exitCode(), replay.err());
            assertTrue(replay.out().contains(": TIMEOUT after 5000 ticks"), "the found map times out: " + replay.out());
            assertEquals("timeout", t.get("found_accident"));
        }
        assertEquals(3, falsified, "3 of the 4 timeout trials are falsified (the preset's comment)");
    }

    @Test
    void aRequirementNeverViolatedIsCensoredAtTheBudgetInEveryTrial() throws IOException {
        Path folder = reference();
        List<Map<String, String>> car = ResultsFolders.csvRows(folder.resolve("campaign.csv")).stream()
                .filter(t -> t.get("requirement").equals("car")).toList();
        assertEquals(4, car.size());
        for (Map<String, String> t : car) {
            assertEquals("false", t.get("falsified"), t.toString());
            assertEquals(Long.toString(BUDGET), t.get("survival_ticks"), t.toString());
            assertTrue(Long.parseLong(t.get("ticks_to_failure")) >= BUDGET, "it spent its budget: " + t);
            assertEquals("ticks", t.get("stopped_by"));
            assertEquals("", t.get("found_map"));
        }
        for (Map<String, String> d : ResultsFolders.csvRows(folder.resolve("campaign-drivers.csv"))) {
            if (d.get("requirement").equals("car")) {
                assertEquals("0", d.get("falsified"));
                assertEquals("not reached", d.get("km_median_ticks"));
                assertEquals("", d.get("mean_ticks_to_failure"), "no falsified trial to average");
            }
        }
        String verdict = Files.readString(folder.resolve("verdict.txt"));
        assertTrue(verdict.contains("car, random against coverage-search: neither falsified it in any trial."), verdict);
        assertTrue(verdict.contains("timeout, random against coverage-search: falsified in 1 against 2 trials (only random"
                + " in 0, only coverage-search in 1: cannot reach 0.05)"), verdict);
    }

    @Test
    void twoShardsMergedWriteTheSameBytesAsTheWholeCampaign() throws IOException {
        List<String> shards = new ArrayList<>();
        for (int k = 1; k <= 2; k++) {
            Path shard = dir.resolve("shard-" + k);
            CliRunner r = CliRunner.run("run", TINY, "--shard", k + "/2", "--out", shard.toString(), "--threads", "1");
            assertEquals(0, r.exitCode(), r.err());
            assertFalse(Files.exists(shard.resolve("campaign.csv")), "a shard writes no campaign tables of its share");
            shards.add(shard.toString());
        }
        CliRunner report = CliRunner.run("report", shards.get(0));
        assertEquals(ExitCode.USAGE, report.exitCode(), report.err());
        assertTrue(report.err().contains("once all 2 shards are merged"), report.err());
        Path merged = dir.resolve("merged");
        List<String> args = new ArrayList<>(List.of("merge"));
        args.addAll(shards);
        args.addAll(List.of("--out", merged.toString()));
        CliRunner m = CliRunner.run(args.toArray(String[]::new));
        assertEquals(0, m.exitCode(), m.err());
        ResultsFolders.assertSameCampaign(reference(), merged);
        CliRunner one = CliRunner.run("merge", shards.get(0), "--out", dir.resolve("half").toString());
        assertEquals(ExitCode.USAGE, one.exitCode());
        assertTrue(one.err().contains("merge needs all 2 shards"), one.err());
    }

    @Test
    void requirementsThatCannotBeMetAreRefusedWithOneMessageNamingTheFix() throws IOException {
        String base = "master_seed=1\ndrivers=random\n";
        String campaign = "protocol=campaign\ntrials=2\ntick_budget=100\n";
        Map<String, String> cases = Map.of(
                campaign + "variants=none\nrequirements=timeout,speeding\n", "no requirement 'speeding'; the requirements"
                        + " are obstacle, car, leaveroad, centreline, timeout, controller",
                campaign + "variants=none\nrequirements=car,car\n", "names car twice",
                campaign + "faults=17\nrequirements=timeout\n", "set variants=none, or remove requirements=",
                "candidates=10\nvariants=none\nrequirements=timeout\n", "add protocol=campaign with variants=none");
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
        CliRunner shards = CliRunner.run("run", TINY, "--shard", "1/3", "--out", dir.resolve("three").toString());
        assertEquals(ExitCode.USAGE, shards.exitCode());
        assertTrue(shards.err().contains("has 2 trials, so no more than 2 shards"), shards.err());
    }

    @Test
    void aCampaignFolderKeepsWhatItFalsifiesSoReportWritesTheSameBytesAgain() throws IOException {
        Path copy = dir.resolve("copy");
        ResultsFolders.copy(reference(), copy);
        Files.delete(copy.resolve("campaign.csv"));
        CliRunner r = CliRunner.run("report", copy.toString());
        assertEquals(0, r.exitCode(), r.err());
        ResultsFolders.assertSameCampaign(reference(), copy);
        assertTrue(Files.readString(copy.resolve("campaign.properties")).contains("requirements=car,timeout\n"));
    }

    @Test
    void aFolderThatKeepsOnlyCampaignCsvHasItsIntervalsAndPairedTestsWrittenAgainFromItsTrials() throws IOException {
        Path kept = dir.resolve("kept");
        ResultsFolders.copyCampaignTrials(reference(), kept);
        CliRunner r = CliRunner.run("report", kept.toString());
        assertEquals(0, r.exitCode(), r.err());
        ResultsFolders.assertSameCampaignFiles(reference(), kept);
    }
}
