package sitcov.experiment;

/**
 * What one driver may spend in a replication: {@code amount} of one measure (candidates drawn,
 * simulated ticks, or wall-clock nanoseconds), and never more than {@code candidateLimit} candidates.
 */
record Budget(StopReason measure, long amount, long candidateLimit) {
    static Budget candidates(int n) {
        return new Budget(StopReason.CANDIDATES, n, n);
    }

    /** The budget of a later driver: what the first driver spent, in the experiment's kind of budget. */
    static Budget after(BudgetKind kind, DriverSpend first, long firstNanos, int candidateLimit) {
        return kind == BudgetKind.TICKS ? new Budget(StopReason.TICKS, first.ticks(), candidateLimit)
                : new Budget(StopReason.WALL_CLOCK, firstNanos, candidateLimit);
    }
}
