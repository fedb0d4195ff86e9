package sitcov.results;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinCar;
import sitcov.coverage.GridDefinition;
import sitcov.drivers.Drivers;
import sitcov.experiment.BudgetKind;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ExperimentRunner;
import sitcov.experiment.Shard;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;
import sitcov.report.ResultsRecorder;

class JournalFilesTest {
    @TempDir
    Path dir;

    private Manifest recordTinyExperiment() throws Exception {
        ExperimentConfig config = new ExperimentConfig("older", 5, 3, 1, FaultSet.parse("19"), BudgetKind.TICKS,
                GridDefinition.paper(), List.of("random"), List.of(), 3, FaultyRuns.UNTIL_VERDICT);
        Manifest manifest = new Manifest(config, "test", Shard.WHOLE, false, false);
        ResultsRecorder recorder = ResultsRecorder.create(dir, manifest, Map.of(), System::nanoTime, BuiltinCar.FACTORY);
        new ExperimentRunner(config, Drivers.standard(), Shard.WHOLE, recorder.journal(), 1, System::nanoTime,
                List.of(recorder), BuiltinCar.SOURCE).run();
        return Manifest.read(dir);
    }

    @Test
    void aFolderWhoseDriversCsvLacksAColumnIsRefusedNamingItEvenWithEveryRowChecked() throws Exception {
        Manifest manifest = recordTinyExperiment();
        assertEquals(1, JournalFiles.read(dir, manifest).finished().size());
        // As an older sitcov without cells_covered would have written it: header and rows without it, each row checked.
        JournalCheck check = JournalCheck.of(manifest);
        assertTrue(check.active(), "the folder's rows carry checks");
        Path drivers = dir.resolve(ResultsFolder.DRIVERS);
        List<String> lines = Files.readAllLines(drivers);
        int at = List.of(lines.get(0).split(",")).indexOf("cells_covered");
        assertTrue(at > 0, lines.get(0));
        StringBuilder older = new StringBuilder(check.header(without(DriversCsv.HEADER, at), false)).append('\n');
        for (String line : lines.subList(1, lines.size())) {
            older.append(check.rows(without(line.substring(0, line.lastIndexOf(',')), at) + "\n"));
        }
        Files.writeString(drivers, older);

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> JournalFiles.read(dir, manifest));
        assertTrue(e.getMessage().startsWith(drivers + ":1: the header lacks the column 'cells_covered' this sitcov reads"),
                e.getMessage());
    }

    private static String without(String line, int at) {
        List<String> values = new ArrayList<>(List.of(line.split(",", -1)));
        values.remove(at);
        return String.join(",", values);
    }
}
