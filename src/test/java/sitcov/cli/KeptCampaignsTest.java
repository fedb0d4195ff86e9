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
 * The campaigns kept under experiments/results publish tables their README says {@code report} computes again from
 * campaign.csv alone; each is computed again here and compared with what is published, byte for byte.
 */
class KeptCampaignsTest {
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
}
