package sitcov.judge;

import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Failure;

/**
 * A requirement of the controller under test that its own runs are judged by, with no other version to
 * compare: no accident of one type, reaching the Target in time, and answering every tick as a controller.
 * A falsification campaign of the reference seeks a map on which it violates one
 * (experiments/README.md, "Requirement campaigns: where your controller itself fails").
 */
public enum Requirement {
    OBSTACLE(AccidentType.CLASHWITHOBSTACLE, "no clash with a parked car", "clashes with a parked car"),
    CAR(AccidentType.CLASHWITHOTHERCAR, "no clash with a moving car it is to blame for", "clashes with a moving car"),
    LEAVEROAD(AccidentType.LEAVEROAD, "no leaving the road", "leaves the road"),
    CENTRELINE(AccidentType.CROSSCENTRELINE, "no crossing of the centre line without an excuse", "crosses the centre line"),
    TIMEOUT(AccidentType.TIMEOUT, "the Target reached within the timeout", "misses the Target"),
    /** The one requirement without an accident type, so without a robustness. */
    CONTROLLER(null, "no controller failure (a command every tick, in time, within the world's rules)",
            "fails as a controller");

    private final AccidentType accident;
    private final String sentence;
    private final String violated;

    Requirement(AccidentType accident, String sentence, String violated) {
        this.accident = accident;
        this.sentence = sentence;
        this.violated = violated;
    }

    /** Its name in presets, folders and tables: an accident type's word, or {@code controller}. */
    public String key() {
        return accident == null ? "controller" : accident.word();
    }

    /** What it asks of the controller, in a few words. */
    public String sentence() {
        return sentence;
    }

    /** What a run that violates it does, in three or four words (a figure's panel has no room for more). */
    public String violated() {
        return violated;
    }

    /** The accident type whose robustness ρ measures how near a run came to violating it; empty for {@link #CONTROLLER}. */
    public Optional<AccidentType> robustness() {
        return Optional.ofNullable(accident);
    }

    /** How {@code run} violated it: the first of its failures the run had, in {@link Failure} order; empty if none. */
    public Optional<Failure> violation(RunSummary run) {
        if (accident != null) {
            return run.count(accident) > 0 ? Optional.of(Failure.of(accident)) : Optional.empty();
        }
        return Failure.of(run.outcome());
    }

    /** Whether a run that had {@code failures} violated it. */
    public boolean violatedBy(Set<Failure> failures) {
        return accident != null ? failures.contains(Failure.of(accident)) : failures.stream().anyMatch(Failure::ofController);
    }

    /**
     * The requirements a campaign falsifies unless its preset names them: all of them, but for the builtin car
     * ({@code controllerCanFail} false) the controller's own: it runs in sitcov's process with no time limit.
     */
    public static List<Requirement> defaults(boolean controllerCanFail) {
        Set<Requirement> all = EnumSet.allOf(Requirement.class);
        if (!controllerCanFail) {
            all.remove(CONTROLLER);
        }
        return List.copyOf(all);
    }

    /**
     * The requirement named {@code key}.
     *
     * @throws IllegalArgumentException naming every key there is
     */
    public static Requirement ofKey(String key) {
        for (Requirement r : values()) {
            if (r.key().equals(key.strip().toLowerCase(Locale.ROOT))) {
                return r;
            }
        }
        throw new IllegalArgumentException("no requirement '" + key.strip() + "'; the requirements are "
                + String.join(", ", Arrays.stream(values()).map(Requirement::key).toList()));
    }

    /** {@code keys} as a preset writes them, comma-separated, in requirement order. */
    public static String format(List<Requirement> requirements) {
        return String.join(",", requirements.stream().sorted().map(Requirement::key).toList());
    }
}
