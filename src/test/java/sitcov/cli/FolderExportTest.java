package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.xpath.XPathFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import sitcov.results.ResultsFolder;

/**
 * {@code export RESULTS --found} on a folder of one map, on which both drivers found faults 2 and 4: four found
 * rows, two runs (one a fault), one map.
 */
class FolderExportTest {
    private static Path folder;

    @TempDir
    Path dir;

    private static synchronized Path folder() throws IOException {
        if (folder == null) {
            Path work = ResultsFolders.scratch("sitcov-folder-export-test");
            Path preset = work.resolve("one-map.properties");
            List<String> lines = new ArrayList<>();
            for (String line : Files.readAllLines(Path.of(ResultsFolders.TINY))) {
                lines.add(line.startsWith("faults=") ? "faults=2,4" : line.startsWith("candidates=") ? "candidates=1"
                        : line.startsWith("replications=") ? "replications=1" : line);
            }
            Files.write(preset, lines);
            CliRunner r = CliRunner.run("run", preset.toString(), "--out", work.resolve("results").toString());
            assertEquals(ExitCode.OK, r.exitCode(), r.err());
            folder = work.resolve("results");
        }
        return folder;
    }

    @Test
    void rowsOnOneMapShareOneRoadFileAndSituationAndEveryScenarioNamesARoadFileThatIsThere() throws Exception {
        List<Map<String, String>> found = found(folder());
        Set<String> maps = new HashSet<>(found.stream().map(r -> r.get("external_seed")).toList());
        assertTrue(found.size() >= 2 && maps.size() < found.size(), "the folder has two found rows on one map: " + found);
        CliRunner r = CliRunner.run("export", folder().toString(), "--found", "--out", dir.toString());
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        List<String> files = files(dir);
        assertEquals(maps.size(), files.stream().filter(f -> f.endsWith(".xodr")).count(), files.toString());
        for (String f : files) {
            if (f.endsWith(".xosc")) {
                String road = logicFile(dir.resolve(f));
                assertTrue(Files.isRegularFile(dir.resolve(road)), f + " names " + road + ", which is not there: " + files);
            }
        }
        for (Map<String, String> row : index(dir)) {
            assertEquals("map-" + row.get("external_seed") + ".xodr", row.get("road_file"), row.toString());
            assertEquals("map-" + row.get("external_seed") + ".xosc", row.get("situation_file"), row.toString());
            assertEquals(row.get("road_file"), logicFile(dir.resolve(row.get("run_file"))), row.toString());
        }
    }

    @Test
    void rowsThatRanTheSameRunShareItsFileAndRowsOfAnotherFaultHaveTheirOwn() throws Exception {
        CliRunner r = CliRunner.run("export", folder().toString(), "--found", "--out", dir.toString());
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        List<Map<String, String>> index = index(dir);
        assertEquals(found(folder()).size(), index.size());
        Map<String, String> runOfFault = new HashMap<>();
        for (Map<String, String> row : index) {
            String fault = row.get("fault");
            String shared = runOfFault.putIfAbsent(fault, row.get("run_file"));
            if (shared != null) {
                assertEquals(shared, row.get("run_file"), "rows of fault " + fault + " on one map with one seed");
            }
            Document run = parse(dir.resolve(row.get("run_file")));
            assertEquals("faults " + fault, egoProperty(run, "sitcovFaults"), row.get("run_file"));
            assertEquals(row.get("internal_seed"), egoProperty(run, "sitcovInternalSeed"), row.get("run_file"));
        }
        assertEquals(Set.of("2", "4"), runOfFault.keySet(), "both faults are found: " + index);
        assertNotEquals(runOfFault.get("2"), runOfFault.get("4"));
        assertEquals(runOfFault.size(), files(dir).stream().filter(f -> f.endsWith("-run.xosc")).count(), files(dir).toString());
    }

    /** The found rows of runs.csv, each as its cells by column name. */
    private static List<Map<String, String>> found(Path results) throws IOException {
        return table(results.resolve(ResultsFolder.RUNS)).stream().filter(r -> r.get("detection").equals("FOUND")).toList();
    }

    private static List<Map<String, String>> index(Path export) throws IOException {
        return table(export.resolve("index.csv"));
    }

    private static List<Map<String, String>> table(Path csv) throws IOException {
        List<String> lines = Files.readAllLines(csv);
        String[] header = lines.get(0).split(",");
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

    private static List<String> files(Path folder) throws IOException {
        try (Stream<Path> s = Files.list(folder)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    private static String logicFile(Path scenario) throws Exception {
        return XPathFactory.newInstance().newXPath().evaluate("/OpenSCENARIO/RoadNetwork/LogicFile/@filepath", parse(scenario));
    }

    private static Document parse(Path file) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(file.toFile());
    }

    /** A property of the car under test, where a recorded run says what it is. */
    private static String egoProperty(Document doc, String name) throws Exception {
        return XPathFactory.newInstance().newXPath().evaluate(
                "/OpenSCENARIO/Entities/ScenarioObject[@name='ego']//Property[@name='" + name + "']/@value", doc);
    }
}
