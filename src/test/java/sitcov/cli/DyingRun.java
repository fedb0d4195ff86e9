package sitcov.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import sitcov.drivers.Drivers;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ExperimentEvent;
import sitcov.experiment.ExperimentRunner;
import sitcov.experiment.Shard;
import sitcov.report.ResultsRecorder;
import sitcov.results.Manifest;

/**
 * A run of a preset that dies as under kill -9: the JVM halts, with no shutdown hook, no close and no
 * flush, right after the results recorder has taken the judged map number {@code MAPS} (its recordings
 * written, its rows handed to the journal). A test starts it in a process of its own and resumes what it
 * leaves: {@code DyingRun PRESET FOLDER MAPS}.
 */
public final class DyingRun {
    /** The exit status the halt gives, as a shell reports a process killed by signal 9. */
    static final int KILLED = 137;

    private DyingRun() {
    }

    public static void main(String[] args) throws Exception {
        Path preset = Path.of(args[0]);
        Path folder = Path.of(args[1]);
        int maps = Integer.parseInt(args[2]);
        ExperimentConfig config = Preset.read(preset, null, Drivers.standard()).config();
        ResultsRecorder recorder = ResultsRecorder.create(folder, new Manifest(config, Version.current(), Shard.WHOLE,
                false, false), Map.of(), System::nanoTime, sitcov.builtin.BuiltinCar.FACTORY);
        int[] judged = {0};
        Controllers.Opened controllers = Controllers.open(config, folder);
        new ExperimentRunner(config, Drivers.standard(), Shard.WHOLE, recorder.journal(), 1, System::nanoTime,
                List.of(recorder, e -> {
                    if (e instanceof ExperimentEvent.MapJudged && ++judged[0] == maps) {
                        Runtime.getRuntime().halt(KILLED);
                    }
                }), controllers.reference(), controllers.variants()).run();
        throw new IllegalStateException("the run ended before map " + maps + " was judged");
    }
}
