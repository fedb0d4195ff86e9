package sitcov.export;

import java.util.Arrays;
import java.util.Optional;

/**
 * The OpenSCENARIO XML version an export is written for. 1.0 is the default: what CARLA's
 * ScenarioRunner reads. Later versions differ only where 1.0's way became deprecated, and are written the way
 * that replaced it.
 */
public enum ScenarioVersion {
    V1_0(0), V1_1(1), V1_2(2), V1_3(3);

    private final int minor;

    ScenarioVersion(int minor) {
        this.minor = minor;
    }

    public int minor() {
        return minor;
    }

    /** As users write it: "1.0" to "1.3". */
    public String label() {
        return "1." + minor;
    }

    public static Optional<ScenarioVersion> parse(String text) {
        return Arrays.stream(values()).filter(v -> v.label().equals(text.trim())).findFirst();
    }

    /** A trajectory sits inside a TrajectoryRef from 1.1 on; directly inside its action before. */
    boolean wrapsTrajectories() {
        return minor >= 1;
    }

    /**
     * What a scenario changes as it runs is a variable from 1.2 on (VariableDeclarations, VariableAction), which
     * deprecated setting a parameter; before, a parameter.
     */
    boolean hasVariables() {
        return minor >= 2;
    }

    /** A position reached is a DistanceCondition from 1.2 on, which deprecated the ReachPositionCondition. */
    boolean reachesByDistance() {
        return minor >= 2;
    }
}
