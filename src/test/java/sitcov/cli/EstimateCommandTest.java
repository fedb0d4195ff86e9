package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class EstimateCommandTest {
    private static final String TINY = """
            protocol=estimate
            master_seed=5
            replications=2
            mc_maps=3
            ce_stages=1
            ce_maps=3
            is_maps=3
            """;

    @TempDir
    static Path dir;
    static Path preset;
    static CliRunner whole;

    @BeforeAll
    static void runTheTinyEstimateWhole() throws Exception {
        preset = dir.resolve("tiny.properties");
        Files.writeString(preset, TINY);
        whole = CliRunner.run("estimate", preset.toString(), "--out", dir.resolve("whole").toString(), "--threads", "2");
    }

    @Test
    void anEstimateWritesEveryRunAndItsEstimates() throws Exception {
        assertEquals(0, whole.exitCode(), whole.err());
        List<String> samples = Files.readAllLines(dir.resolve("whole/samples.csv"));
        // per replication 3 plain Monte Carlo, 3 cross-entropy and 3 importance-sampling maps
        assertEquals(1 + 2 * 9, samples.size());
        assertTrue(whole.out().contains("Plain Monte Carlo: 6 runs"), whole.out());
        assertTrue(Files.readString(dir.resolve("whole/manifest.properties")).contains("complete=true"));
        assertTrue(Files.readAllLines(dir.resolve("whole/estimate.csv")).get(1).startsWith("mc,any,6,"));
    }

    @Test
    void shardsRunThroughRunAndMergedAreTheWholeEstimateByteForByte() throws Exception {
        Path s1 = dir.resolve("s1");
        Path s2 = dir.resolve("s2");
        assertEquals(0, CliRunner.run("run", preset.toString(), "--shard", "1/2", "--out", s1.toString()).exitCode());
        assertEquals(0, CliRunner.run("estimate", preset.toString(), "--shard", "2/2", "--out", s2.toString()).exitCode());
        CliRunner merged = CliRunner.run("merge", s2.toString(), s1.toString(), "--out", dir.resolve("merged").toString());
        assertEquals(0, merged.exitCode(), merged.err());
        try (Stream<Path> files = Files.list(dir.resolve("whole"))) {
            for (Path f : files.toList()) {
                assertArrayEquals(Files.readAllBytes(f), Files.readAllBytes(dir.resolve("merged").resolve(f.getFileName())),
                        f.getFileName().toString());
            }
        }
    }

    @Test
    void mergeRefusesAMissingShardNamingIt() {
        Path lone = dir.resolve("lone");
        assertEquals(0, CliRunner.run("estimate", preset.toString(), "--shard", "1/2", "--out", lone.toString()).exitCode());
        CliRunner r = CliRunner.run("merge", lone.toString(), "--out", dir.resolve("m2").toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("shards 2/2 of 2 are missing"), r.err());
    }

    @Test
    void aKeyThatIsNotAnEstimatesIsRefusedNamingTheKeys() throws Exception {
        Path bad = dir.resolve("bad.properties");
        Files.writeString(bad, TINY + "candidates=50\n");
        CliRunner r = CliRunner.run("estimate", bad.toString(), "--out", dir.resolve("bad").toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("candidates= is not a key of an estimate"), r.err());
        assertFalse(r.err().contains("Exception"), r.err());
    }

    @Test
    void moreShardsThanReplicationsAreRefused() {
        CliRunner r = CliRunner.run("estimate", preset.toString(), "--shard", "3/3", "--dry-run");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("no more than 2 shards"), r.err());
    }

    @Test
    void anUnknownSiteIsRefusedNamingTheSites() throws Exception {
        Path bad = dir.resolve("sites.properties");
        Files.writeString(bad, TINY + "sites=junctions,weather\n");
        CliRunner r = CliRunner.run("estimate", bad.toString(), "--dry-run");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("'weather', not a draw of the generator; the sites are junctions, parked"), r.err());
    }

    @Test
    void helpListsEstimate() {
        assertTrue(CliRunner.run("--help").out().contains("estimate"));
    }
}
