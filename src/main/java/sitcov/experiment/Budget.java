package sitcov.experiment;

/**
 * What one driver may spend in a replication, by kind: the leading driver's number of candidates, or
 * a following driver's share measured on what the leader spends, in simulated ticks or in wall-clock
 * time (experiments/README.md, "Budgets"). Every kind also caps the candidates a driver may draw.
 */
sealed interface Budget {
    /** The most candidates the driver may draw. */
    int candidateLimit();

    /** Why a driver stopped that drew {@link #candidateLimit()} candidates. */
    StopReason atLimit();

    /** Why a driver stopped that spent its budget before reaching the limit. */
    StopReason spentOut();

    /** Whether a driver below its limit that has spent {@code ticks} in {@code elapsedNanos} may draw again; may wait. */
    boolean left(long ticks, long elapsedNanos, Runnable checkHalt);

    /** How much of the budget {@code drawn} candidates, {@code ticks} and {@code elapsedNanos} are (not clamped). */
    double share(int drawn, long ticks, long elapsedNanos);

    /** The driver has now spent {@code ticks} in all. */
    default void charged(long ticks) {
    }

    /** The driver has judged {@code run} (after {@link #charged}). */
    default void judged(MapRun run) {
    }

    /**
     * A campaign trial's budget: {@code ticks} simulated ticks for every driver alike, ended early by
     * the first map that falsifies the campaign's target (its variant found under the differential oracle,
     * or its requirement violated by the reference). One instance per driver session, so its state is the session's.
     */
    final class FixedTicks implements Budget {
        private final long ticks;
        private final int candidateLimit;
        private final CampaignTarget target;
        private boolean falsified;

        FixedTicks(long ticks, int candidateLimit, CampaignTarget target) {
            this.ticks = ticks;
            this.candidateLimit = candidateLimit;
            this.target = target;
        }

        @Override
        public int candidateLimit() {
            return candidateLimit;
        }

        @Override
        public StopReason atLimit() {
            return StopReason.CANDIDATE_LIMIT;
        }

        @Override
        public StopReason spentOut() {
            return falsified ? StopReason.FALSIFIED : StopReason.TICKS;
        }

        @Override
        public boolean left(long spent, long elapsedNanos, Runnable checkHalt) {
            return !falsified && spent < ticks;
        }

        @Override
        public double share(int drawn, long spent, long elapsedNanos) {
            return falsified ? 1 : (double) spent / ticks;
        }

        @Override
        public void judged(MapRun run) {
            falsified |= target.falsifiedOn(run);
        }
    }

    /** The leading driver's budget: {@code count} candidates; it tells the {@code lead} what it spends as it goes. */
    record Candidates(int count, Lead lead) implements Budget {
        @Override
        public int candidateLimit() {
            return count;
        }

        @Override
        public StopReason atLimit() {
            return StopReason.CANDIDATES;
        }

        @Override
        public StopReason spentOut() {
            return StopReason.CANDIDATES;
        }

        @Override
        public boolean left(long ticks, long elapsedNanos, Runnable checkHalt) {
            return true;
        }

        @Override
        public double share(int drawn, long ticks, long elapsedNanos) {
            return (double) drawn / count;
        }

        @Override
        public void charged(long ticks) {
            lead.spent(ticks);
        }
    }

    /** A following driver's budget: the simulated ticks the leader spends (reproducible). */
    record TicksOfLead(Lead lead, int candidateLimit) implements Budget {
        @Override
        public StopReason atLimit() {
            return StopReason.CANDIDATE_LIMIT;
        }

        @Override
        public StopReason spentOut() {
            return StopReason.TICKS;
        }

        @Override
        public boolean left(long ticks, long elapsedNanos, Runnable checkHalt) {
            return lead.ticksLeft(ticks, checkHalt);
        }

        @Override
        public double share(int drawn, long ticks, long elapsedNanos) {
            long amount = lead.ticksSoFar();
            return amount == 0 ? 1 : (double) ticks / amount;
        }
    }

    /** A following driver's budget: the wall-clock time the leader spends (the paper's; not reproducible). */
    record WallClockOfLead(Lead lead, int candidateLimit) implements Budget {
        @Override
        public StopReason atLimit() {
            return StopReason.CANDIDATE_LIMIT;
        }

        @Override
        public StopReason spentOut() {
            return StopReason.WALL_CLOCK;
        }

        @Override
        public boolean left(long ticks, long elapsedNanos, Runnable checkHalt) {
            return lead.nanosLeft(elapsedNanos);
        }

        @Override
        public double share(int drawn, long ticks, long elapsedNanos) {
            long amount = lead.nanosSoFar(elapsedNanos);
            return amount == 0 ? 1 : (double) elapsedNanos / amount;
        }
    }
}
