package sitcov.oracle;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/**
 * The result of one run: how it ended, every accident event in order, the contacts the blame
 * rules excused, the ticks simulated, both seeds that reproduce it, and how close it came to each
 * accident ({@link Margins}: near misses, reported beside accidents and never counted as failures).
 */
public record RunResult(long externalSeed, long internalSeed, Outcome outcome, List<Accident> accidents,
                        Map<Blame, Integer> excusedContacts, long ticks, Margins margins) {
    public RunResult {
        accidents = List.copyOf(accidents);
        excusedContacts = Map.copyOf(excusedContacts);
        java.util.Objects.requireNonNull(margins, "margins");
    }

    /** A result whose margins were not measured. */
    public RunResult(long externalSeed, long internalSeed, Outcome outcome, List<Accident> accidents,
                     Map<Blame, Integer> excusedContacts, long ticks) {
        this(externalSeed, internalSeed, outcome, accidents, excusedContacts, ticks, Margins.UNKNOWN);
    }

    public boolean hasAccident() {
        return !accidents.isEmpty();
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
