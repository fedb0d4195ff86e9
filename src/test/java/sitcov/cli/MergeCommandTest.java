package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.results.ResultsFolder;

class MergeCommandTest {
    @TempDir
    static Path shards;

    @BeforeAll
    static void runTheThreeShards() {
        for (int k = 1; k <= 3; k++) {
            CliRunner r = CliRunner.run("run", ResultsFolders.TINY, "--shard", k + "/3", "--out",
                    shards.resolve("s" + k).toString(), "--threads", "1");
            assertEquals(0, r.exitCode(), r.err());
        }
    }

    private static String shard(int k) {
        return shards.resolve("s" + k).toString();
    }

    @Test
    void eachShardRunsOnlyItsShareOfTheReplications() throws Exception {
        for (int k = 1; k <= 3; k++) {
            List<String> drivers = Files.readAllLines(shards.resolve("s" + k).resolve(ResultsFolder.DRIVERS));
            assertEquals(List.of(k - 1 + ",coverage-filter", k - 1 + ",random"),
                    drivers.stream().skip(1).map(l -> l.substring(0, l.indexOf(',', l.indexOf(',') + 1))).toList());
            assertTrue(Files.readString(shards.resolve("s" + k).resolve(ResultsFolder.MANIFEST)).contains("\nshard=" + k + "/3\n"));
        }
    }

    @Test
    void threeShardsMergedEqualTheUnshardedRun(@TempDir Path out) throws Exception {
        Path merged = out.resolve("merged");
        CliRunner r = CliRunner.run("merge", shard(3), shard(1), shard(2), "--out", merged.toString());
        assertEquals(0, r.exitCode(), r.err());
        ResultsFolders.assertSameResults(ResultsFolders.tinyReference(), merged);
        assertTrue(r.out().contains("Merged 3 shards into " + merged), r.out());
    }

    @Test
    void aMissingOrRepeatedShardIsRefused(@TempDir Path out) {
        CliRunner missing = CliRunner.run("merge", shard(1), shard(3), "--out", out.resolve("m").toString());
        assertEquals(2, missing.exitCode());
        assertTrue(missing.err().contains("shard 2/3 missing"), missing.err());
        CliRunner twice = CliRunner.run("merge", shard(1), shard(2), shard(2), shard(3), "--out", out.resolve("t").toString());
        assertEquals(2, twice.exitCode());
        assertTrue(twice.err().contains("shard 2/3 is given twice"), twice.err());
        assertTrue(!Files.exists(out.resolve("m")) && !Files.exists(out.resolve("t")), "a refused merge writes nothing");
    }

    @Test
    void aShardOfAnotherExperimentIsRefusedNamingWhatDiffers(@TempDir Path out) {
        Path other = out.resolve("other");
        CliRunner o = CliRunner.run("run", ResultsFolders.TINY, "--seed", "8", "--shard", "2/3", "--out", other.toString());
        assertEquals(0, o.exitCode(), o.err());
        CliRunner r = CliRunner.run("merge", shard(1), other.toString(), shard(3), "--out", out.resolve("m").toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("is not a shard of the same experiment") && r.err().contains("master_seed 7 vs 8"),
                r.err());
    }

    @Test
    void aWholeRunOrAnIncompleteShardIsRefused(@TempDir Path out) throws Exception {
        CliRunner whole = CliRunner.run("merge", ResultsFolders.tinyReference().toString(), "--out", out.resolve("w").toString());
        assertEquals(2, whole.exitCode());
        assertTrue(whole.err().contains("holds a whole run, not a shard"), whole.err());
        Path copy = out.resolve("s2");
        ResultsFolders.copy(shards.resolve("s2"), copy);
        Files.writeString(copy.resolve(ResultsFolder.MANIFEST),
                Files.readString(copy.resolve(ResultsFolder.MANIFEST)).replace("complete=true", "complete=false"));
        CliRunner incomplete = CliRunner.run("merge", shard(1), copy.toString(), shard(3), "--out", out.resolve("i").toString());
        assertEquals(2, incomplete.exitCode());
        assertTrue(incomplete.err().contains("is not complete; finish it with run --resume"), incomplete.err());
    }

    @Test
    void aShardEditedByHandIsRefusedNamingTheFile(@TempDir Path out) throws Exception {
        Path copy = out.resolve("s2");
        ResultsFolders.copy(shards.resolve("s2"), copy);
        Path drivers = copy.resolve(ResultsFolder.DRIVERS);
        Files.writeString(drivers, Files.readString(drivers).replace("\n1,random,", "\n1,random,1"));
        CliRunner r = CliRunner.run("merge", shard(1), copy.toString(), shard(3), "--out", out.resolve("m").toString());
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains(drivers + ":3: this row was changed after sitcov wrote it"), r.err());
        assertTrue(!Files.exists(out.resolve("m")), "a refused merge writes nothing");
    }

    @Test
    void theTemporaryFilesAKilledShardLeftAreNotCopied(@TempDir Path out) throws Exception {
        Path copy = out.resolve("s2");
        ResultsFolders.copy(shards.resolve("s2"), copy);
        Files.createDirectories(copy.resolve(ResultsFolder.SITUATIONS));
        Files.writeString(copy.resolve(ResultsFolder.SITUATIONS).resolve(".search-r1-0.situation5521.tmp"), "sitcov-sit");
        Path merged = out.resolve("merged");
        CliRunner r = CliRunner.run("merge", shard(1), copy.toString(), shard(3), "--out", merged.toString());
        assertEquals(0, r.exitCode(), r.err());
        ResultsFolders.assertSameResults(ResultsFolders.tinyReference(), merged);
    }

    @Test
    void ofTwoMergesIntoOneFolderOneWritesItAndTheOtherIsRefusedInOneLine(@TempDir Path out) throws Exception {
        Path merged = out.resolve("merged");
        List<CliRunner> r = ConcurrentRunsTest.twice("merge", shard(1), shard(2), shard(3), "--out", merged.toString());
        CliRunner winner = r.get(0).exitCode() == 0 ? r.get(0) : r.get(1);
        CliRunner loser = winner == r.get(0) ? r.get(1) : r.get(0);
        assertEquals(0, winner.exitCode(), winner.err());
        assertEquals(2, loser.exitCode(), loser.err());
        // refused by the lock while the other writes, or by what it wrote once it is done
        assertTrue(loser.err().contains("merge: another run or merge is writing into " + merged)
                || loser.err().contains("holds files already") || loser.err().contains("is not an empty folder"), loser.err());
        assertTrue(!loser.err().contains("Exception") && !loser.err().contains("\tat "), loser.err());
        ResultsFolders.assertSameResults(ResultsFolders.tinyReference(), merged);
    }
}
