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
    void mergeRefusesASampleChangedByHandNamingTheFileAndWritesNothing() throws Exception {
        Path edited = dir.resolve("edited");
        ResultsFolders.copy(dir.resolve("whole"), edited);
        assertTrue(Files.readString(edited.resolve("manifest.properties")).contains("samples_sha256="), "a digest kept");
        Path samples = edited.resolve("samples.csv");
        // a run's failure flipped: a plausible edit that would change every estimate
        List<String> lines = new java.util.ArrayList<>(Files.readAllLines(samples));
        lines.set(1, lines.get(1).replaceFirst(",0,0,0,0,0,0,0,", ",0,0,0,0,1,0,0,"));
        assertFalse(lines.get(1).equals(Files.readAllLines(samples).get(1)), "the row was edited: " + lines.get(1));
        Files.write(samples, lines);
        Path out = dir.resolve("from-edited");
        CliRunner r = CliRunner.run("merge", edited.toString(), "--out", out.toString());
        assertEquals(2, r.exitCode(), r.err());
        assertTrue(r.err().contains("samples.csv was changed after sitcov wrote it (it does not match samples_sha256"), r.err());
        assertFalse(Files.exists(out.resolve("estimate.csv")), "nothing estimated from an edited samples.csv");
    }

    @Test
    void aFolderWrittenBeforeItsDigestsMergesWithAWarningAndStaysUnattested() throws Exception {
        Path old = dir.resolve("old");
        ResultsFolders.copy(dir.resolve("whole"), old);
        Path manifest = old.resolve("manifest.properties");
        Files.write(manifest, Files.readAllLines(manifest).stream()
                .filter(l -> !l.contains("_sha256=") && !l.startsWith("checks=")).toList());
        Path out = dir.resolve("from-old");
        CliRunner r = CliRunner.run("merge", old.toString(), "--out", out.toString());
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.err().contains("keeps no digest of its samples"), r.err());
        assertArrayEquals(Files.readAllBytes(dir.resolve("whole/estimate.csv")), Files.readAllBytes(out.resolve("estimate.csv")));
        assertFalse(Files.readString(out.resolve("manifest.properties")).contains("_sha256="), "left unattested");
    }

    @Test
    void aPlanChangedByHandInTheManifestIsRefusedNamingTheKey() throws Exception {
        Path edited = dir.resolve("edited-plan");
        ResultsFolders.copy(dir.resolve("whole"), edited);
        Path manifest = edited.resolve("manifest.properties");
        List<String> lines = Files.readAllLines(manifest);
        assertTrue(lines.contains("defensive=0.1"), lines.toString());
        Files.write(manifest, lines.stream().map(l -> l.equals("defensive=0.1") ? "defensive=0.3" : l).toList());
        CliRunner r = CliRunner.run("merge", edited.toString(), "--out", dir.resolve("from-edited-plan").toString());
        assertEquals(2, r.exitCode(), r.err());
        assertTrue(r.err().contains("manifest.properties: defensive was changed after sitcov wrote it"), r.err());
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
