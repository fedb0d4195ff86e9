package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.results.ResultsFolder;

class InputLimitsTest {
    @TempDir
    Path dir;

    private static void refused(String expected, String... args) {
        CliRunner r = CliRunner.run(args);
        assertEquals(ExitCode.USAGE, r.exitCode(), String.join(" ", args) + ": " + r.err());
        assertTrue(r.err().contains(expected), String.join(" ", args) + ": " + r.err());
        assertTrue(!r.err().contains("Exception") && !r.err().contains("\tat "), r.err());
    }

    @Test
    void countsNameTheirLimits() {
        refused("--maps needs a whole number from 1 to 20000, not '2147483647'", "faults", "--calibrate", "--maps",
                "2147483647");
        refused("--maps needs a whole number from 1 to 1000000, not '99999999999'", "simulate", "--maps", "99999999999");
        refused("--threads needs a whole number from 1 to 4096, not '0'", "run", ResultsFolders.TINY, "--threads", "0");
    }

    @Test
    void threadsBeyondTheCoresAreCappedAndTheFolderSaysHowManyRan() throws Exception {
        int cores = Runtime.getRuntime().availableProcessors();
        Path out = dir.resolve("threads");
        CliRunner r = CliRunner.run("run", "src/test/resources/presets/tiny-sweep.properties", "--threads", "4000", "--out",
                out.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.err().contains("--threads 4000 is more than the " + cores + " cores here; using " + cores), r.err());
        assertTrue(Files.readAllLines(out.resolve(ResultsFolder.EXECUTION)).contains("threads=" + cores));
    }

    @Test
    void presetMistakesNameTheKeyAndTheFile() throws Exception {
        String base = Files.readString(Path.of(ResultsFolders.TINY));
        Path twice = dir.resolve("twice.properties");
        Files.writeString(twice, base + "candidates=13\n");
        refused(twice + ":11: the key 'candidates' is given twice; keep one", "run", twice.toString());
        Path none = dir.resolve("none.properties");
        Files.writeString(none, base.replace("faults=14,19", "faults=NONE"));
        refused("faults=NONE leaves no fault to find; name at least one", "run", none.toString());
        Path exclusion = dir.resolve("exclusion.properties");
        Files.writeString(exclusion, base.replace("faults=14,19", "faults=-2-4"));
        refused("'-2-4' removes faults, but nothing comes before it", "run", exclusion.toString());
        Path latin1 = dir.resolve("latin1.properties");
        Files.write(latin1, (base + "description=caf\u00e9\n").getBytes(StandardCharsets.ISO_8859_1));
        refused(latin1 + " is not UTF-8 text", "run", latin1.toString());
        assertTrue(!Files.exists(Path.of("target", "results", "twice-seed7")), "nothing ran");
    }

    @Test
    void aResultsFolderUnderAFileIsRefusedBeforeAnythingRuns() throws Exception {
        Path file = dir.resolve("file.txt");
        Files.writeString(file, "x");
        refused("cannot create the results folder " + file.resolve("results"), "run", ResultsFolders.TINY, "--out",
                file.resolve("results").toString());
    }

    @Test
    void anEmptyPathIsShownAsTwoQuotes() {
        refused("cannot read --load '' (", "map", "--load", "");
        refused("run: --resume '' is not a folder", "run", "--resume", "");
    }

    @Test
    void theOptionsOfAnUnknownOptionsMessageComeInAFixedOrder() {
        CliRunner r = CliRunner.run("run", "smoke", "--sed", "1");
        assertTrue(r.err().contains("the options are --again, --controller, --dry-run, --fork, --out, --record, --replications, --resume, --seed, --shard, --threads, --variants."), r.err());
    }

    @Test
    void aCampaignsCandidateLimitIsHeldToTheLimitItsDocsGive() throws Exception {
        int limit = sitcov.experiment.ExperimentConfig.MAX_CANDIDATES;
        assertEquals(10_000_000, limit);
        // the docs write it in groups of three digits
        String written = "10 000 000";
        String docs = Files.readString(Path.of("experiments", "README.md"));
        String row = docs.lines().filter(l -> l.startsWith("| `candidate_limit` | a safety limit on the candidates of one"
                + " trial")).findFirst().orElseThrow();
        assertTrue(row.contains("at most " + written), row);
        assertTrue(Files.readString(Path.of("src", "main", "java", "sitcov", "cli", "README.md"))
                .contains(written + " in a campaign"), "the commands' limits name it too");
        String base = Files.readString(Path.of("src", "test", "resources", "presets", "campaign-tiny.properties"));
        Path preset = dir.resolve("campaign-limit.properties");
        Files.writeString(preset, base + "candidate_limit=" + (limit + 1) + "\n");
        refused("candidate_limit= needs a whole number from 1 to " + limit + ", not '" + (limit + 1) + "'", "run",
                preset.toString(), "--out", dir.resolve("never").toString());
        Files.writeString(preset, base + "candidate_limit=" + limit + "\n");
        CliRunner r = CliRunner.run("run", preset.toString(), "--dry-run");
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().contains("campaign of 2 faults") && r.out().contains(": sound; a dry run"), r.out());
        assertTrue(!Files.exists(dir.resolve("never")), "nothing ran");
    }

    @Test
    void aGridWhoseCellsCannotBeCountedIsRefused() throws Exception {
        StringBuilder edges = new StringBuilder();
        for (int i = 0; i <= 200; i++) {
            edges.append(' ').append(i);
        }
        Path grid = dir.resolve("huge-grid.txt");
        Files.writeString(grid, "sitcov-grid 1\ncriterion target-obstacle" + edges + "\ncriterion start-target" + edges
                + "\ncriterion previous-junction-target" + edges + "\n");
        refused("a grid of more than 1000000 cells is too large to count", "coverage", "--maps", "10", "--grid",
                grid.toString());
    }

    @Test
    void aPresetsCountsHaveTheLimitsOfTheCommandLineAndAreRefusedBeforeAnythingIsPlanned() throws Exception {
        String base = Files.readString(Path.of(ResultsFolders.TINY));
        String[][] cases = {
            {"replications=2147483647", "replications= needs a whole number from 1 to 1000000, not '2147483647'"},
            {"replications=0", "replications= needs a whole number from 1 to 1000000, not '0'"},
            {"candidates=99999999999", "candidates= needs a whole number from 1 to 10000000, not '99999999999'"},
            {"candidate_limit=2000000000", "candidate_limit= needs a whole number from 1 to 100000000"},
            {"sweep=5,20000000", "sweep= needs a whole number from 1 to 10000000, not '20000000'"},
        };
        for (String[] c : cases) {
            String key = c[0].substring(0, c[0].indexOf('='));
            Path preset = dir.resolve("counts.properties");
            Files.writeString(preset, base.replaceAll("(?m)^" + key + "=.*$", "") + "\n" + c[0] + "\n");
            refused(c[1], "run", preset.toString(), "--out", dir.resolve("never").toString());
        }
        // a sweep's map sets over all its budgets are held to the limit of replications
        Path sweep = dir.resolve("sweep.properties");
        Files.writeString(sweep, base.replace("replications=3", "replications=400000") + "sweep=5,10,20\n");
        refused("sweep= has 3 budgets of 400000 map sets each (replications=), 1200000 in all; the limit is 1000000",
                "run", sweep.toString(), "--out", dir.resolve("never").toString());
        refused("--replications needs a whole number from 1 to 1000000, not '1000001'", "run", ResultsFolders.TINY,
                "--replications", "1000001");
        assertTrue(!Files.exists(dir.resolve("never")), "nothing ran");
    }
}
