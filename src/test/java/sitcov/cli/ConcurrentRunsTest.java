package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CyclicBarrier;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.results.ResultsFolder;

class ConcurrentRunsTest {
    @TempDir
    Path dir;

    /** Starts {@code args} on two threads at once and returns both outcomes. */
    static List<CliRunner> twice(String... args) throws Exception {
        CyclicBarrier start = new CyclicBarrier(2);
        List<CompletableFuture<CliRunner>> runs = new ArrayList<>();
        for (int i = 0; i < 2; i++) {
            runs.add(CompletableFuture.supplyAsync(() -> {
                try {
                    start.await();
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
                return CliRunner.run(args);
            }));
        }
        return List.of(runs.get(0).get(), runs.get(1).get());
    }

    @Test
    void ofTwoRunsIntoOneFolderExactlyOneProceeds() throws Exception {
        Path out = dir.resolve("shared");
        List<CliRunner> r = twice("run", ResultsFolders.TINY, "--out", out.toString(), "--threads", "1");
        CliRunner winner = r.get(0).exitCode() == 0 ? r.get(0) : r.get(1);
        CliRunner loser = winner == r.get(0) ? r.get(1) : r.get(0);
        assertEquals(0, winner.exitCode(), winner.err());
        assertEquals(2, loser.exitCode(), loser.err());
        assertTrue(loser.err().contains("another run or merge is writing into") || loser.err().contains("not an empty folder")
                || loser.err().contains("holds files already"), loser.err());
        ResultsFolders.assertSameResults(ResultsFolders.tinyReference(), out);
        assertTrue(!Files.exists(out.resolve(ResultsFolder.LOCK)), "the lock is gone once the run ended");
    }

    @Test
    void twoDefaultRunsRacingForOneNameGetTwoFolders() throws Exception {
        String name = "race-" + ProcessHandle.current().pid() + "-" + System.nanoTime();
        Path preset = dir.resolve(name + ".properties");
        Files.writeString(preset, Files.readString(Path.of(ResultsFolders.TINY)).replace("replications=3", "replications=1"));
        List<CliRunner> r = twice("run", preset.toString(), "--threads", "1");
        try {
            assertEquals(0, r.get(0).exitCode(), r.get(0).err());
            assertEquals(0, r.get(1).exitCode(), r.get(1).err());
            String a = r.get(0).out().lines().filter(l -> l.startsWith("Results in ")).findFirst().orElseThrow();
            String b = r.get(1).out().lines().filter(l -> l.startsWith("Results in ")).findFirst().orElseThrow();
            assertNotEquals(a.substring(0, a.indexOf(" (")), b.substring(0, b.indexOf(" (")));
        } finally {
            try (Stream<Path> made = Files.list(Path.of("target", "results"))) {
                for (Path folder : made.filter(p -> p.getFileName().toString().startsWith(name)).toList()) {
                    try (Stream<Path> files = Files.walk(folder)) {
                        for (Path f : files.sorted(Comparator.reverseOrder()).toList()) {
                            Files.delete(f);
                        }
                    }
                }
            }
        }
    }
}
