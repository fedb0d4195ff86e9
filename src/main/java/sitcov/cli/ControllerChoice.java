package sitcov.cli;

import java.nio.file.Path;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.control.ControllerSource;
import sitcov.experiment.ExperimentConfig;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.vehicles.BuiltinCar;

/**
 * The controller a preset or {@code --controller} names: {@code builtin}, or {@code exec:COMMAND
 * ARGS…} for a program speaking the JSON-Lines protocol (README, "Test your own controller").
 */
final class ControllerChoice {
    static final String EXEC = "exec:";
    static final String BUILTIN_WITH = "builtin:";

    private ControllerChoice() {
    }

    /** The spec as given, once it names a controller sitcov can start. */
    static String check(String spec) throws UsageException {
        if (spec.equals(ExperimentConfig.BUILTIN)) {
            return spec;
        }
        if (spec.startsWith(BUILTIN_WITH)) {
            planted(spec);
            return spec;
        }
        if (spec.startsWith(EXEC) && !spec.substring(EXEC.length()).isBlank()) {
            return spec;
        }
        throw new UsageException("controller=" + spec + " names no controller; use 'builtin', 'builtin:FAULTS' (the"
                + " builtin car with those faults always on, e.g. builtin:16) or 'exec:COMMAND ARGS…'"
                + " (e.g. exec:python3 experiments/controllers/lane_follower.py).");
    }

    private static Set<Fault> planted(String spec) throws UsageException {
        try {
            Set<Fault> faults = FaultSet.parse(spec.substring(BUILTIN_WITH.length()));
            if (faults.isEmpty()) {
                throw new IllegalArgumentException("it names no fault");
            }
            return faults;
        } catch (IllegalArgumentException e) {
            throw new UsageException("controller=" + spec + ": " + e.getMessage() + "; name faults by id after"
                    + " 'builtin:', e.g. builtin:16 or builtin:16,17.");
        }
    }

    /** Starts what {@code spec} names; a controller program's logs go into {@code folder}. */
    static ControllerSource open(String spec, Path folder) throws UsageException {
        check(spec);
        if (spec.equals(ExperimentConfig.BUILTIN)) {
            return BuiltinCar.SOURCE;
        }
        if (spec.startsWith(BUILTIN_WITH)) {
            ControllerFactory factory = BuiltinCar.withPlanted(planted(spec));
            return new ControllerSource() {
                @Override
                public ControllerFactory forThisThread() {
                    return factory;
                }

                @Override
                public String spec() {
                    return spec;
                }
            };
        }
        throw new UsageException("controller programs arrive with the protocol");
    }
}
