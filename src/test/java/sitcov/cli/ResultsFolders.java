package sitcov.cli;

import java.util.Map;

import java.util.HashMap;

import java.util.ArrayList;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import sitcov.results.ResultsFolder;

/** Fixtures for tests of results folders: the tiny preset's reference run, and byte-for-byte comparison. */
final class ResultsFolders {
    static final String TINY = "src/test/resources/presets/tiny.properties";
    private static final java.util.Map<String, Path> RAN = new java.util.HashMap<>();

    private ResultsFolders() {
    }

    /** The tiny preset run once, whole and uninterrupted, shared by the tests that compare against it. */
    static Path tinyReference() throws IOException {
        return ranOnce(TINY);
    }

    /**
     * {@code preset} run once, whole, on 2 threads, into a folder of its own, shared by the tests that
     * only read it; the run must succeed and print its verdict.
     */
    static synchronized Path ranOnce(String preset) throws IOException {
        Path folder = RAN.get(preset);
        if (folder == null) {
            folder = scratch("sitcov-reference").resolve("whole");
            CliRunner r = CliRunner.run("run", preset, "--out", folder.toString(), "--threads", "2");
            assertEquals(0, r.exitCode(), r.err());
            assertTrue(r.out().contains("Verdict"), "run prints the verdict: " + r.out());
            RAN.put(preset, folder);
        }
        return folder;
    }

    /**
     * A new folder for a fixture shared by several tests (a JUnit {@code @TempDir} lives for one test or class): under
     * the build's target/, so a clean build removes it rather than leaving it in the system's temporary folder.
     */
    static Path scratch(String prefix) throws IOException {
        Path root = Files.createDirectories(Path.of("target", "test-scratch"));
        return Files.createTempDirectory(root, prefix).toAbsolutePath();
    }

    /** The files of a folder that hold results (everything but the timed files), as paths within it, sorted. */
    static List<String> resultFiles(Path folder) throws IOException {
        try (Stream<Path> s = Files.walk(folder)) {
            return s.filter(Files::isRegularFile).map(p -> folder.relativize(p).toString().replace('\\', '/'))
                    .filter(n -> !ResultsFolder.TIMED.contains(n)).sorted().toList();
        }
    }

    /** A copy of a results folder, its subfolders included. */
    static void copy(Path from, Path to) throws IOException {
        try (Stream<Path> s = Files.walk(from)) {
            for (Path p : s.toList()) {
                Path target = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(p, target);
                }
            }
        }
    }

    /** Asserts that two results folders hold the same result files, byte for byte. */
    static void assertSameResults(Path expected, Path actual) throws IOException {
        List<String> files = resultFiles(expected);
        assertTrue(files.contains(ResultsFolder.RUNS), expected + " holds no runs.csv");
        assertEquals(files, resultFiles(actual), "the result files of " + actual);
        for (String f : files) {
            assertArrayEquals(Files.readAllBytes(expected.resolve(f)), Files.readAllBytes(actual.resolve(f)),
                    f + " differs between " + expected + " and " + actual);
        }
    }

    /** The files of a campaign's folder that hold results, its sub-folders' included: every file but timed ones and locks. */
    static List<String> campaignFiles(Path folder) throws IOException {
        try (Stream<Path> s = Files.walk(folder)) {
            return s.filter(Files::isRegularFile)
                    .filter(p -> !ResultsFolder.TIMED.contains(p.getFileName().toString())
                            && !p.getFileName().toString().equals(ResultsFolder.LOCK))
                    .map(p -> folder.relativize(p).toString().replace('\\', '/')).sorted().toList();
        }
    }

    /** Asserts that two campaign folders hold the same result files, sub-folders included, byte for byte. */
    static void assertSameCampaign(Path expected, Path actual) throws IOException {
        List<String> files = campaignFiles(expected);
        assertTrue(files.contains(ResultsFolder.CAMPAIGN_TRIALS), expected + " holds no campaign.csv");
        assertEquals(files, campaignFiles(actual), "the result files of " + actual);
        for (String f : files) {
            assertArrayEquals(Files.readAllBytes(expected.resolve(f)), Files.readAllBytes(actual.resolve(f)),
                    f + " differs between " + expected + " and " + actual);
        }
    }

    /**
     * A copy of a campaign's folder as a published one keeps it: campaign.csv and what names the campaign
     * (campaign.properties, grid.txt), none of its other files or sub-folders.
     */
    static void copyCampaignTrials(Path from, Path to) throws IOException {
        Files.createDirectories(to);
        for (String f : List.of(ResultsFolder.CAMPAIGN_TRIALS, ResultsFolder.CAMPAIGN_MANIFEST, "grid.txt")) {
            Files.copy(from.resolve(f), to.resolve(f));
        }
    }

    /** Asserts that {@code actual} holds each of the campaign's own files (not its sub-folders') byte for byte. */
    static void assertSameCampaignFiles(Path expected, Path actual) throws IOException {
        List<String> own = campaignFiles(expected).stream().filter(f -> !f.contains("/")).toList();
        assertTrue(own.contains(ResultsFolder.VERDICT) && own.contains(ResultsFolder.CAMPAIGN_STATS), "a campaign's own files: " + own);
        assertEquals(own, campaignFiles(actual), "the result files of " + actual);
        for (String f : own) {
            assertArrayEquals(Files.readAllBytes(expected.resolve(f)), Files.readAllBytes(actual.resolve(f)),
                    f + " differs between " + expected + " and " + actual);
        }
    }

    /** The rows of a CSV file without quoted fields, by column name. */
    static List<Map<String, String>> csvRows(Path csv) throws IOException {
        List<String> lines = Files.readAllLines(csv);
        String[] header = lines.get(0).split(",", -1);
        List<Map<String, String>> rows = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            String[] cells = line.split(",", -1);
            Map<String, String> row = new HashMap<>();
            for (int i = 0; i < header.length; i++) {
                row.put(header[i], cells[i]);
            }
            rows.add(row);
        }
        return rows;
    }
}
