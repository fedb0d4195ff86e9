package sitcov.oracle;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/**
 * The result of one run: how it ended, every accident event in order, the contacts the blame
 * rules excused, the ticks simulated, both seeds that reproduce it, and how close it came to each
 * accident ({@link Margins}: near misses, reported beside accidents and never counted as failures),
 * and, when the controller failed, why (empty otherwise), and how many ticks' commands the world
 * clamped to the car's limits.
 */
public record RunResult(long externalSeed, long internalSeed, Outcome outcome, List<Accident> accidents,
                        Map<Blame, Integer> excusedContacts, long ticks, Margins margins, String failureReason,
                        long clampedTicks) {
    public RunResult {
        accidents = List.copyOf(accidents);
        excusedContacts = Map.copyOf(excusedContacts);
        java.util.Objects.requireNonNull(margins, "margins");
        java.util.Objects.requireNonNull(failureReason, "failureReason");
    }

    /** A result whose clamped ticks were not counted. */
    public RunResult(long externalSeed, long internalSeed, Outcome outcome, List<Accident> accidents,
                     Map<Blame, Integer> excusedContacts, long ticks, Margins margins, String failureReason) {
        this(externalSeed, internalSeed, outcome, accidents, excusedContacts, ticks, margins, failureReason, 0);
    }

    /** A run whose controller did not fail: no reason to keep. */
    public RunResult(long externalSeed, long internalSeed, Outcome outcome, List<Accident> accidents,
                     Map<Blame, Integer> excusedContacts, long ticks, Margins margins) {
        this(externalSeed, internalSeed, outcome, accidents, excusedContacts, ticks, margins, "");
    }

    /** A result whose margins were not measured. */
    public RunResult(long externalSeed, long internalSeed, Outcome outcome, List<Accident> accidents,
                     Map<Blame, Integer> excusedContacts, long ticks) {
        this(externalSeed, internalSeed, outcome, accidents, excusedContacts, ticks, Margins.UNKNOWN);
    }

    public boolean hasAccident() {
        return !accidents.isEmpty();
    }

    /** The controller's failure the run ended in, if it did ({@link #failureReason()} says why). */
    public java.util.Optional<Failure> controllerFailure() {
        return Failure.of(outcome);
    }

    /** Whether the run failed: an accident, or the controller failed. */
    public boolean failed() {
        return hasAccident() || controllerFailure().isPresent();
    }

    public long count(AccidentType type) {
        return accidents.stream().filter(a -> a.type() == type).count();
    }

    /** Accident counts for every type, in type order. */
    public Map<AccidentType, Long> countsByType() {
        Map<AccidentType, Long> counts = new EnumMap<>(AccidentType.class);
        for (AccidentType t : AccidentType.values()) {
            counts.put(t, count(t));
        }
        return counts;
    }
}
