package sitcov.judge;

import java.util.List;
import java.util.Objects;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Margins;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;

/**
 * What an experiment keeps of one simulated run: how it ended, its ticks, its accident events by
 * type, how close it came to each accident, why its controller failed if it did (else empty), and
 * how many ticks' commands the world clamped (runs.csv keeps it only where it keeps the reason).
 */
public record RunSummary(Outcome outcome, long ticks, List<Long> accidents, Margins margins, String failureReason,
                         long clampedTicks) {
    public RunSummary {
        Objects.requireNonNull(failureReason, "failureReason");
        accidents = List.copyOf(accidents);
        if (accidents.size() != AccidentType.values().length) {
            throw new IllegalArgumentException("a run summary counts each of the " + AccidentType.values().length
                    + " accident types, got " + accidents.size());
        }
        Objects.requireNonNull(margins, "margins");
    }

    /** A summary whose clamped ticks were not kept. */
    public RunSummary(Outcome outcome, long ticks, List<Long> accidents, Margins margins, String failureReason) {
        this(outcome, ticks, accidents, margins, failureReason, 0);
    }

    /** A summary of a run whose controller did not fail, or whose reason was not kept. */
    public RunSummary(Outcome outcome, long ticks, List<Long> accidents, Margins margins) {
        this(outcome, ticks, accidents, margins, "");
    }

    /** A summary whose margins were not measured. */
    public RunSummary(Outcome outcome, long ticks, List<Long> accidents) {
        this(outcome, ticks, accidents, Margins.UNKNOWN);
    }

    public static RunSummary of(RunResult r) {
        return new RunSummary(r.outcome(), r.ticks(), List.copyOf(r.countsByType().values()), r.margins(),
                r.failureReason(), r.clampedTicks());
    }

    /**
     * Whether {@code replayed}, a run of the same map and seeds run again, is this run as a results folder
     * recorded it. Margins a folder did not measure (rows written before it kept them) are not compared.
     */
    public boolean agrees(RunSummary replayed) {
        return equals(margins.known() ? replayed : new RunSummary(replayed.outcome, replayed.ticks, replayed.accidents,
                Margins.UNKNOWN, replayed.failureReason, replayed.clampedTicks));
    }

    public long count(AccidentType type) {
        return accidents.get(type.ordinal());
    }

    public boolean hasAccident() {
        return accidents.stream().anyMatch(n -> n > 0);
    }
}
