package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.xpath.XPathConstants;
import javax.xml.xpath.XPathFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import sitcov.export.AsamSchemas;
import sitcov.export.OpenDrive;
import sitcov.export.ScenarioVersion;
import sitcov.results.ResultsFolder;
import sitcov.results.SignedEdits;
import sitcov.world.MapGenerator;

/**
 * {@code sitcov export}: a seed, a situation file, a row of a results folder or all its found runs written as
 * OpenDRIVE and OpenSCENARIO files that parse; bad input refused with one message and exit 2, nothing written.
 */
class ExportCommandTest {
    /**
     * Results folders of three candidates, one replication: fault 4 is found on some maps, some of its runs short
     * (a row's export records the faulty run to its end), and fault 10 is found on none.
     */
    private static Path finding;
    private static Path findingNothing;

    @TempDir
    Path dir;

    private static synchronized Path finding() throws IOException {
        if (finding == null) {
            finding = smallRun("4");
        }
        return finding;
    }

    private static synchronized Path findingNothing() throws IOException {
        if (findingNothing == null) {
            findingNothing = smallRun("10");
        }
        return findingNothing;
    }

    private static Path smallRun(String fault) throws IOException {
        Path work = ResultsFolders.scratch("sitcov-export-test");
        Path preset = work.resolve("small.properties");
        List<String> lines = new ArrayList<>();
        for (String line : Files.readAllLines(Path.of(ResultsFolders.TINY))) {
            lines.add(line.startsWith("faults=") ? "faults=" + fault
                    : line.startsWith("candidates=") ? "candidates=3"
                    : line.startsWith("replications=") ? "replications=1" : line);
        }
        Files.write(preset, lines);
        CliRunner r = CliRunner.run("run", preset.toString(), "--out", work.resolve("results").toString(), "--threads", "2");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        return work.resolve("results");
    }

    /** The rows (1 = first under the header) of a folder's runs.csv whose fault was found, each as its cells. */
    private static List<String[]> foundRows(Path results) throws IOException {
        List<String> rows = Files.readAllLines(results.resolve(ResultsFolder.RUNS));
        List<String> header = List.of(rows.get(0).split(","));
        int detection = header.indexOf("detection");
        List<String[]> found = new ArrayList<>();
        for (int i = 1; i < rows.size(); i++) {
            String[] cells = rows.get(i).split(",", -1);
            if (cells[detection].equals("FOUND")) {
                String[] withRow = new String[cells.length + 1];
                withRow[0] = Integer.toString(i);
                System.arraycopy(cells, 0, withRow, 1, cells.length);
                found.add(withRow);
            }
        }
        return found;
    }

    private static String column(Path results, String[] foundRow, String name) throws IOException {
        List<String> header = List.of(Files.readAllLines(results.resolve(ResultsFolder.RUNS)).get(0).split(","));
        return foundRow[header.indexOf(name) + 1];
    }

    @Test
    void aSeedIsExportedAsItsRoadsAndItsSituationWhichNamesThem() throws Exception {
        CliRunner r = CliRunner.run("export", "--seed", "5", "--out", dir.toString(), "--osc", "1.2");
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        assertEquals(List.of("map-5.xodr", "map-5.xosc"), files(dir));
        assertEquals(OpenDrive.document(MapGenerator.generate(5)), Files.readString(dir.resolve("map-5.xodr")),
                "the command writes what the export makes of the map");
        Document road = parse(dir.resolve("map-5.xodr"));
        assertTrue(number(road, "count(/OpenDRIVE/road)") > MapGenerator.generate(5).layout().roads().size(),
                "the roads are cut into pieces at the junctions");
        Document situation = parse(dir.resolve("map-5.xosc"));
        assertEquals("2", text(situation, "/OpenSCENARIO/FileHeader/@revMinor"), "--osc 1.2");
        assertEquals("map-5.xodr", text(situation, "/OpenSCENARIO/RoadNetwork/LogicFile/@filepath"));
        assertEquals("ego", text(situation, "/OpenSCENARIO/Entities/ScenarioObject[1]/@name"));
    }

    @Test
    void aFolderUnderAFileIsRefusedByNameBeforeAnythingIsWritten() throws Exception {
        Path file = dir.resolve("a-file");
        Files.writeString(file, "kept");
        CliRunner r = CliRunner.run("export", "--seed", "5", "--out", file.resolve("x").toString());
        assertEquals(ExitCode.USAGE, r.exitCode(), r.err());
        assertTrue(r.err().contains(file.resolve("x") + " cannot be made: " + file.toAbsolutePath() + " is a file"), r.err());
        assertEquals("kept", Files.readString(file));
        assertEquals(List.of("a-file"), files(dir));
    }

    @Test
    void aSituationFileIsExportedUnderItsOwnNameAsItsSeedIs() throws Exception {
        Path situation = dir.resolve("five.situation");
        assertEquals(ExitCode.OK, CliRunner.run("map", "--seed", "5", "--save", situation.toString()).exitCode());
        Path bySeed = dir.resolve("by-seed");
        Path byFile = dir.resolve("by-file");
        assertEquals(ExitCode.OK, CliRunner.run("export", "--seed", "5", "--out", bySeed.toString()).exitCode());
        CliRunner r = CliRunner.run("export", "--load", situation.toString(), "--out", byFile.toString());
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        assertEquals(List.of("five.xodr", "five.xosc"), files(byFile));
        assertArrayEquals(Files.readAllBytes(bySeed.resolve("map-5.xodr")), Files.readAllBytes(byFile.resolve("five.xodr")));
        assertEquals(Files.readString(bySeed.resolve("map-5.xosc")).replace("\"map-5.xodr\"", "\"five.xodr\""),
                Files.readString(byFile.resolve("five.xosc")), "the same situation, naming its own road file");
    }

    @Test
    void aFoundRowIsExportedWithItsRunAndItsFaultFreeTwinReplayedFromTheFolder() throws Exception {
        String[] row = foundRows(finding()).get(0);
        String n = row[0];
        CliRunner r = CliRunner.run("export", finding().toString(), "--row", n, "--out", dir.toString());
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        assertEquals(List.of("row-" + n + "-run-fault-free.xosc", "row-" + n + "-run.xosc", "row-" + n + ".xodr", "row-" + n + ".xosc"),
                files(dir));
        for (String run : List.of("row-" + n + "-run.xosc", "row-" + n + "-run-fault-free.xosc")) {
            Document doc = parse(dir.resolve(run));
            assertEquals(column(finding(), row, "external_seed"), egoProperty(doc, "sitcovExternalSeed"), run);
            assertEquals(column(finding(), row, "internal_seed"), egoProperty(doc, "sitcovInternalSeed"), run);
            assertEquals("row-" + n + ".xodr", text(doc, "/OpenSCENARIO/RoadNetwork/LogicFile/@filepath"), run);
            // a row's runs are recorded to their ends
            assertEquals(Long.parseLong(egoProperty(doc, "sitcovTicks")) - 1,
                    Long.parseLong(egoProperty(doc, "sitcovLastTickRecorded")), run);
        }
        assertTrue(egoProperty(parse(dir.resolve("row-" + n + "-run.xosc")), "sitcovFaults").matches(".*\\b4\\b.*"));
        assertFalse(egoProperty(parse(dir.resolve("row-" + n + "-run-fault-free.xosc")), "sitcovFaults").matches(".*\\b4\\b.*"));
        // the row found its fault: the faulty run marks the accident that did, its fault-free twin none
        assertTrue(egoProperty(parse(dir.resolve("row-" + n + "-run.xosc")), "sitcovFoundBy").startsWith("accident"));
        assertEquals("", egoProperty(parse(dir.resolve("row-" + n + "-run-fault-free.xosc")), "sitcovFoundBy"));
    }

    @Test
    void everyFoundRunOfAFolderIsExportedAndIndexedWithTheAccidentThatFoundIt() throws Exception {
        List<String[]> found = foundRows(finding());
        assertTrue(found.size() >= 2, "the small run finds fault 4 on more than one map: " + found.size());
        CliRunner r = CliRunner.run("export", finding().toString(), "--found", "--out", dir.toString());
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        assertTrue(r.err().contains("export: found runs judged again: " + found.size() + "/" + found.size() + " (100%)"),
                "each found run is judged again, with progress: " + r.err());
        List<String> index = Files.readAllLines(dir.resolve("index.csv"));
        List<String> header = List.of(index.get(0).split(","));
        assertEquals(found.size(), index.size() - 1, String.join("\n", index));
        for (int i = 0; i < found.size(); i++) {
            String[] cells = index.get(i + 1).split(",", -1);
            String[] row = found.get(i);
            assertEquals(row[0], cells[header.indexOf("row")]);
            assertEquals(column(finding(), row, "new_accident"), cells[header.indexOf("new_accident")]);
            assertEquals(column(finding(), row, "external_seed"), cells[header.indexOf("external_seed")]);
            String roadFile = cells[header.indexOf("road_file")];
            parse(dir.resolve(roadFile));
            Document situation = parse(dir.resolve(cells[header.indexOf("situation_file")]));
            assertEquals(roadFile, text(situation, "/OpenSCENARIO/RoadNetwork/LogicFile/@filepath"));
            Document scenario = parse(dir.resolve(cells[header.indexOf("run_file")]));
            assertEquals(roadFile, text(scenario, "/OpenSCENARIO/RoadNetwork/LogicFile/@filepath"));
            // the accident that found the fault is marked in the recorded run, by the ego and in its event's name
            String foundBy = egoProperty(scenario, "sitcovFoundBy");
            String event = text(scenario, "//Event[starts-with(@name, '" + foundBy + ": ')]/@name");
            assertTrue(foundBy.startsWith("accident") && event.startsWith(foundBy + ": "
                    + cells[header.indexOf("new_accident")] + ", ego") && event.contains(" at tick "
                    + cells[header.indexOf("tick")] + " (") && event.endsWith("; it found the fault"),
                    index.get(i + 1) + ": its recorded run marks " + foundBy + ", the event " + event);
        }
    }

    @Test
    void theFoundRunsOfAFolderAreValidOpenDriveAndOpenScenario() throws Exception {
        // 1.0, the default, which ScenarioRunner reads; the export's own tests validate every version
        CliRunner r = CliRunner.run("export", finding().toString(), "--found", "--out", dir.toString());
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        List<String> exported = files(dir);
        assertTrue(exported.size() > 2, exported.toString());
        for (String f : exported) {
            if (f.endsWith(".xodr")) {
                AsamSchemas.assertValid(AsamSchemas.openDrive(), Files.readString(dir.resolve(f)), f);
            } else if (f.endsWith(".xosc")) {
                AsamSchemas.assertValid(AsamSchemas.openScenario(ScenarioVersion.V1_0), Files.readString(dir.resolve(f)), f);
            }
        }
    }

    @Test
    void aRowBeyondTheFolderIsRefusedNamingTheRowsThereAre() throws Exception {
        int rows = Files.readAllLines(finding().resolve(ResultsFolder.RUNS)).size() - 1;
        Path out = dir.resolve("out");
        refused("has rows 1.." + rows + " under its header, not " + (rows + 1),
                "export", finding().toString(), "--row", Integer.toString(rows + 1), "--out", out.toString());
        assertFalse(Files.exists(out) && files(out).size() > 0, "nothing was written");
    }

    @Test
    void aFaultTheFolderDidNotSeedIsRefusedNamingTheFaultsItDid() throws Exception {
        Path out = dir.resolve("out");
        refused("did not seed fault 19; its faults are [4]",
                "export", finding().toString(), "--found", "--fault", "19", "--out", out.toString());
        assertFalse(Files.exists(out) && files(out).size() > 0, "nothing was written");
    }

    @Test
    void foundOnAFolderThatFoundNothingIsRefused() throws Exception {
        assertEquals(List.of(), foundRows(findingNothing()), "fault 10 is found on none of the three maps");
        Path out = dir.resolve("out");
        refused("found a fault; there is nothing to export", "export", findingNothing().toString(), "--found", "--out", out.toString());
        assertFalse(Files.exists(out) && files(out).size() > 0, "nothing was written");
    }

    @Test
    void anExistingOutputFileIsRefusedAndNothingIsOverwrittenOrAdded() throws Exception {
        Path kept = dir.resolve("map-5.xosc");
        Files.writeString(kept, "someone's own scenario\n");
        refused(kept + " already exists", "export", "--seed", "5", "--out", dir.toString());
        assertEquals("someone's own scenario\n", Files.readString(kept, StandardCharsets.UTF_8));
        assertEquals(List.of("map-5.xosc"), files(dir), "the road file was not written beside it either");
    }

    @Test
    void aFolderWhoseFoundRowNoLongerRunsAsRecordedFailsBeforeWritingAnything() throws Exception {
        Path copy = dir.resolve("tampered");
        ResultsFolders.copy(ResultsFolders.tinyReference(), copy);
        List<String> rows = Files.readAllLines(copy.resolve(ResultsFolder.RUNS));
        int found = 1;
        while (!rows.get(found).contains(",FOUND,")) {
            found++;
        }
        int faultFree = found - 1;
        while (!rows.get(faultFree).contains(",NONE,")) {
            faultFree--;
        }
        // as another build of sitcov would have written it: the fault-free run took one tick more
        SignedEdits.editRunsRow(copy, faultFree + 1, line -> {
            String[] cells = line.split(",", -1);
            cells[13] = Long.toString(Long.parseLong(cells[13]) + 1);
            return String.join(",", cells);
        });
        Path out = dir.resolve("out");
        CliRunner r = CliRunner.run("export", copy.toString(), "--found", "--out", out.toString());
        assertEquals(ExitCode.FAILURE, r.exitCode(), r.err());
        assertTrue(r.err().contains("does not replay from its recording ")
                && r.err().contains("the reference's run was recorded in runs.csv as")
                && r.err().contains("Nothing was written."), r.err());
        assertFalse(Files.exists(out), "not one file of the export, nor its folder");
    }

    private static void refused(String expected, String... args) {
        CliRunner r = CliRunner.run(args);
        assertEquals(ExitCode.USAGE, r.exitCode(), String.join(" ", args) + ": " + r.err());
        assertTrue(r.err().contains(expected), String.join(" ", args) + ": " + r.err());
        assertTrue(r.err().startsWith("sitcov: export: ") && r.err().lines().filter(l -> l.startsWith("sitcov:")).count() == 1,
                "one message: " + r.err());
        assertTrue(!r.err().contains("Exception") && !r.err().contains("\tat "), r.err());
    }

    private static List<String> files(Path folder) throws IOException {
        try (Stream<Path> s = Files.list(folder)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    private static Document parse(Path file) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(file.toFile());
    }

    private static String text(Document doc, String xpath) throws Exception {
        return XPathFactory.newInstance().newXPath().evaluate(xpath, doc);
    }

    private static double number(Document doc, String xpath) throws Exception {
        return (Double) XPathFactory.newInstance().newXPath().evaluate(xpath, doc, XPathConstants.NUMBER);
    }

    /** A property of the ego, where a recorded run tells the run ("" when it has none of that name). */
    private static String egoProperty(Document doc, String name) throws Exception {
        return text(doc, "//ScenarioObject[@name='ego']//Property[@name='" + name + "']/@value");
    }
}
