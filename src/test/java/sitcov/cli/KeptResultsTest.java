package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.results.ResultsFolder;

/**
 * The results kept under experiments/results publish files their pages say are computed again from what the folder
 * keeps: a campaign's by {@code report} from campaign.csv alone, an estimate's by {@code merge} from its samples.
 * Each is computed again here and compared with what is published, byte for byte. (The test suites' folders take
 * minutes each: experiments/rederive.sh checks them.)
 */
class KeptResultsTest {
    private static final Path RESULTS = Path.of("experiments/results");

    @TempDir
    Path dir;

    @Test
    void everyKeptCampaignWritesItsPublishedFilesAgainFromItsCampaignCsv() throws IOException {
        List<Path> campaigns;
        try (Stream<Path> s = Files.list(RESULTS)) {
            campaigns = s.filter(p -> Files.isRegularFile(p.resolve(ResultsFolder.CAMPAIGN_MANIFEST))).sorted().toList();
        }
        assertTrue(campaigns.size() >= 3, "the kept campaigns: " + campaigns);
        for (Path kept : campaigns) {
            assertTrue(Files.readString(kept.resolve(ResultsFolder.CAMPAIGN_MANIFEST)).contains("trials_sha256="),
                    kept + " keeps the digest of its campaign.csv, so a hand edit to it is refused");
            Path copy = dir.resolve(kept.getFileName().toString());
            ResultsFolders.copyCampaignTrials(kept, copy);
            CliRunner r = CliRunner.run("report", copy.toString());
            assertEquals(0, r.exitCode(), kept + ": " + r.err());
            List<String> published;
            try (Stream<Path> s = Files.list(kept)) {
                published = s.map(p -> p.getFileName().toString()).filter(f -> !f.equals("README.md")).sorted().toList();
            }
            try (Stream<Path> s = Files.list(copy)) {
                assertEquals(published, s.map(p -> p.getFileName().toString()).sorted().toList(), "the files of " + kept);
            }
            for (String f : published) {
                assertArrayEquals(Files.readAllBytes(kept.resolve(f)), Files.readAllBytes(copy.resolve(f)),
                        kept.resolve(f) + " is not what report computes from its campaign.csv");
            }
        }
    }

    @Test
    void everyKeptEstimateWritesItsPublishedFilesAgainFromItsSamples() throws IOException {
        List<Path> estimates;
        try (Stream<Path> s = Files.walk(RESULTS)) {
            estimates = s.filter(p -> p.getFileName().toString().equals("samples.csv.gz")).map(Path::getParent).sorted().toList();
        }
        assertTrue(estimates.size() >= 3, "the kept estimates: " + estimates);
        for (Path kept : estimates) {
            assertTrue(Files.readString(kept.resolve("manifest.properties")).contains("samples_sha256="),
                    kept + " keeps the digest of its samples, so a hand edit to them is refused");
            Path copy = dir.resolve(kept.getFileName().toString());
            Files.createDirectories(copy);
            List<String> published;
            try (Stream<Path> s = Files.list(kept)) {
                published = s.map(p -> p.getFileName().toString()).filter(f -> !f.endsWith(".gz")).sorted().toList();
            }
            for (String f : published) {
                Files.copy(kept.resolve(f), copy.resolve(f));
            }
            try (java.io.InputStream in = new java.util.zip.GZIPInputStream(Files.newInputStream(kept.resolve("samples.csv.gz")))) {
                Files.copy(in, copy.resolve("samples.csv"));
            }
            Path merged = dir.resolve(kept.getFileName() + "-merged");
            CliRunner r = CliRunner.run("merge", copy.toString(), "--out", merged.toString());
            assertEquals(0, r.exitCode(), kept + ": " + r.err());
            assertTrue(published.contains("estimate.txt") && published.contains("estimate.csv"), kept + ": " + published);
            for (String f : published) {
                assertArrayEquals(Files.readAllBytes(kept.resolve(f)), Files.readAllBytes(merged.resolve(f)),
                        kept.resolve(f) + " is not what merge computes from its samples");
            }
        }
    }
}
