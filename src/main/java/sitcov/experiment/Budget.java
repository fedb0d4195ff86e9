package sitcov.experiment;

/**
 * What one driver may spend in a replication: {@code amount} of one measure (candidates drawn,
 * simulated ticks, or wall-clock nanoseconds), and never more than {@code candidateLimit} candidates.
 * A later driver's amount is what the first driver spends, which it learns from {@code lead} as the
 * first goes on: a budget of ticks or wall-clock time always has a lead, and {@code amount} counts only
 * candidates.
 */
record Budget(StopReason measure, long amount, long candidateLimit, Lead lead) {
    static Budget candidates(int n) {
        return new Budget(StopReason.CANDIDATES, n, n, null);
    }

    /** The budget of a later driver: what the first driver spends, in the experiment's kind of budget. */
    static Budget after(BudgetKind kind, Lead lead, int candidateLimit) {
        return new Budget(kind == BudgetKind.TICKS ? StopReason.TICKS : StopReason.WALL_CLOCK, -1, candidateLimit, lead);
    }
}
