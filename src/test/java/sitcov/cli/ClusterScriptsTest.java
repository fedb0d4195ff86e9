package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Slurm scripts of experiments/cluster, without Slurm: they parse, and submit.sh checks its
 * arguments and the preset (through sitcov itself) before it calls sbatch — here a fake that
 * records its arguments — so a mistake costs no wait in the queue.
 */
class ClusterScriptsTest {
    private static final Path SCRIPTS = Path.of("experiments", "cluster");
    private static final Path BASH = Path.of("/bin/bash");

    @TempDir
    Path dir;

    private Path log;

    /** What a script printed and returned. */
    private record Outcome(int code, String out) {
    }

    @BeforeEach
    void fakeSlurmAndJava() throws IOException {
        assumeTrue(Files.isExecutable(BASH), "bash runs the scripts");
        Path bin = Files.createDirectories(dir.resolve("bin"));
        log = dir.resolve("sbatch.log");
        // sbatch --parsable prints "JOBID;CLUSTER"; this one numbers its calls from 4241
        executable(bin.resolve("sbatch"), "#!/bin/bash\necho \"$*\" >> '" + log + "'\n"
                + "echo \"$((4240 + $(wc -l < '" + log + "')));test\"\n");
        // java -jar JAR ARGS... runs this build's classes instead of a packaged jar
        String javaCommand = ProcessHandle.current().info().command().orElse("java");
        executable(bin.resolve("java"), "#!/bin/bash\nshift 2\nexec '" + javaCommand + "' -cp '"
                + Path.of("target", "classes").toAbsolutePath() + "' sitcov.cli.Main \"$@\"\n");
        Files.writeString(dir.resolve("sitcov.jar"), "");
    }

    private static void executable(Path file, String text) throws IOException {
        Files.writeString(file, text);
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rwxr-xr-x"));
    }

    private Outcome submit(String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(BASH.toString(), SCRIPTS.resolve("submit.sh").toString()));
        command.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        Map<String, String> env = pb.environment();
        env.put("PATH", dir.resolve("bin") + ":" + env.getOrDefault("PATH", "/usr/bin:/bin"));
        env.put("SITCOV_JAR", dir.resolve("sitcov.jar").toString());
        env.remove("JAVA");
        env.remove("JAVA_HOME");
        env.remove("JAVA_OPTS");
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        return new Outcome(p.waitFor(), out);
    }

    @Test
    void everyScriptParses() throws Exception {
        for (String script : List.of("submit.sh", "shards.sbatch", "merge.sbatch")) {
            Process p = new ProcessBuilder(BASH.toString(), "-n", SCRIPTS.resolve(script).toString())
                    .redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertEquals(0, p.waitFor(), script + ": " + out);
        }
    }

    @Test
    void moreShardsThanThePresetsReplicationsAreRefusedBeforeAnythingIsSubmitted() throws Exception {
        // smoke has 2 replications (experiments/smoke.properties)
        Outcome r = submit("smoke", "3", dir.resolve("results").toString());
        assertEquals(2, r.code(), r.out());
        assertTrue(r.out().contains("submit.sh: SHARDS=3 is more than the 2 replications of smoke; each shard needs one:"
                + " submit at most 2 shards."), r.out());
        assertFalse(Files.exists(log), "sbatch was not called");
        assertFalse(Files.exists(dir.resolve("results")), "no results folder was made");
    }

    @Test
    void badArgumentsAndABadPresetAreRefusedWithTheFix() throws Exception {
        Outcome zero = submit("smoke", "0");
        assertEquals(2, zero.code());
        assertTrue(zero.out().contains("SHARDS must be a positive integer, got '0'."), zero.out());
        Outcome missing = submit("no-such-preset", "2");
        assertEquals(2, missing.code());
        assertTrue(missing.out().contains("no preset 'no-such-preset'"), missing.out());
        Path bad = dir.resolve("bad.properties");
        Files.writeString(bad, "master_seed=1\ncandidates=5\ncolour=blue\n");
        Outcome refused = submit(bad.toString(), "1", dir.resolve("results").toString());
        assertEquals(2, refused.code());
        assertTrue(refused.out().contains("unknown key 'colour'"), "sitcov's own message: " + refused.out());
        assertTrue(refused.out().contains("submit.sh: sitcov refused the preset (above); nothing was submitted."),
                refused.out());
        assertFalse(Files.exists(log), "sbatch was not called");
    }

    @Test
    void aSoundSplitSubmitsTheArrayThenTheMergeAfterIt() throws Exception {
        Path results = dir.resolve("results");
        Outcome r = submit("smoke", "2", results.toString());
        assertEquals(0, r.code(), r.out());
        List<String> calls = Files.readAllLines(log);
        assertEquals(2, calls.size(), String.join("\n", calls));
        assertTrue(calls.get(0).contains("--array=1-2 ") && calls.get(0).contains("--output=" + results + "/logs/")
                && calls.get(0).endsWith("shards.sbatch"), calls.get(0));
        assertTrue(calls.get(1).contains("--dependency=afterok:4241 ") && calls.get(1).contains("--output=" + results
                + "/logs/") && calls.get(1).endsWith("merge.sbatch"), calls.get(1));
        assertTrue(r.out().contains("Merge:  job 4242 (after all shards succeed) -> " + results + "/merged"), r.out());
        assertTrue(Files.isDirectory(results.resolve("logs")));
    }
}
