package sitcov.cli;

import java.nio.file.Path;
import sitcov.control.ControllerSource;
import sitcov.experiment.ExperimentConfig;
import sitcov.vehicles.BuiltinCar;

/**
 * The controller a preset or {@code --controller} names: {@code builtin}, or {@code exec:COMMAND
 * ARGS…} for a program speaking the JSON-Lines protocol (README, "Test your own controller").
 */
final class ControllerChoice {
    static final String EXEC = "exec:";

    private ControllerChoice() {
    }

    /** The spec as given, once it names a controller sitcov can start. */
    static String check(String spec) throws UsageException {
        if (spec.equals(ExperimentConfig.BUILTIN)) {
            return spec;
        }
        if (spec.startsWith(EXEC) && !spec.substring(EXEC.length()).isBlank()) {
            return spec;
        }
        throw new UsageException("controller=" + spec + " names no controller; use 'builtin' or 'exec:COMMAND ARGS…'"
                + " (e.g. exec:python3 experiments/controllers/lane_follower.py).");
    }

    /** Starts what {@code spec} names; a controller program's logs go into {@code folder}. */
    static ControllerSource open(String spec, Path folder) throws UsageException {
        check(spec);
        if (spec.equals(ExperimentConfig.BUILTIN)) {
            return BuiltinCar.SOURCE;
        }
        throw new UsageException("controller programs arrive with the protocol");
    }
}
