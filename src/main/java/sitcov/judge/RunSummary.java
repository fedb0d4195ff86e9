package sitcov.judge;

import java.util.List;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;

/** What an experiment keeps of one simulated run: how it ended, its ticks and its accident events by type. */
public record RunSummary(Outcome outcome, long ticks, List<Long> accidents) {
    public RunSummary {
        accidents = List.copyOf(accidents);
        if (accidents.size() != AccidentType.values().length) {
            throw new IllegalArgumentException("a run summary counts each of the " + AccidentType.values().length
                    + " accident types, got " + accidents.size());
        }
    }

    public static RunSummary of(RunResult r) {
        return new RunSummary(r.outcome(), r.ticks(), List.copyOf(r.countsByType().values()));
    }

    public long count(AccidentType type) {
        return accidents.get(type.ordinal());
    }

    public boolean hasAccident() {
        return accidents.stream().anyMatch(n -> n > 0);
    }
}
