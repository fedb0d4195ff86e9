package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.drivers.Drivers;
import sitcov.experiment.BudgetKind;
import sitcov.judge.FaultyRuns;

class PresetTest {
    @Test
    void everyShippedPresetReads() throws Exception {
        List<Path> presets;
        try (Stream<Path> files = Files.list(Path.of("experiments"))) {
            presets = files.filter(f -> f.toString().endsWith(".properties")).sorted().toList();
        }
        assertTrue(presets.size() >= 4, presets.toString());
        for (Path p : presets) {
            if (EstimatePreset.isEstimate(p)) {
                assertEquals(p.getFileName().toString().replace(".properties", ""),
                        EstimatePreset.read(p, null, null, null).name(), p.toString());
                continue;
            }
            Preset preset;
            preset = Preset.read(p, null, Drivers.standard());
            String name = preset.campaign() != null ? preset.campaign().name() : preset.config().name();
            assertEquals(p.getFileName().toString().replace(".properties", ""), name, p.toString());
        }
    }

    @Test
    void theThousandReplicationPresetIsTheSoundPaperComparison() throws Exception {
        var config = Preset.read(Path.of("experiments", "paper-rq1-1000.properties"), null, Drivers.standard()).config();
        assertEquals(1000, config.replications());
        assertEquals(20000, config.candidates());
        assertEquals(BudgetKind.TICKS, config.budget());
        assertEquals(FaultyRuns.UNTIL_VERDICT, config.faultyRuns());
    }

    @Test
    void faultyRunsStopAtTheVerdictUnlessThePresetSaysToEnd(@TempDir Path dir) throws Exception {
        Path smoke = Path.of("experiments", "smoke.properties");
        assertEquals(FaultyRuns.UNTIL_VERDICT, Preset.read(smoke, null, Drivers.standard()).config().faultyRuns());
        Path toEnd = dir.resolve("smoke.properties");
        Files.writeString(toEnd, Files.readString(smoke).replace("grid=experiments", "grid=" + Path.of("experiments")
                .toAbsolutePath()) + "faulty_runs=to-end\n");
        assertEquals(FaultyRuns.TO_END, Preset.read(toEnd, null, Drivers.standard()).config().faultyRuns());
    }
}
