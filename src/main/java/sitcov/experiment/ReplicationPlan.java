package sitcov.experiment;

import java.util.concurrent.atomic.AtomicInteger;

/**
 * The lead/follow protocol of one replication: the preset's first driver leads, with the replication's
 * candidates as its budget; each later driver follows, spending what the leader spends in the
 * experiment's kind of budget, which it learns from the {@link Lead} as the leader goes on. The plan
 * also holds what the drivers share (the maps judged so far, the situation names) and counts the
 * drivers down to the replication's end.
 */
final class ReplicationPlan {
    private final PlannedReplication replication;
    private final BudgetKind kind;
    private final int candidateLimit;
    private final long tickBudget;
    /** What a campaign's trial falsifies; empty in the suites. */
    private final java.util.Optional<CampaignTarget> target;
    private final Lead lead = new Lead();
    private final SharedMaps shared;
    private final AtomicInteger driversLeft;

    ReplicationPlan(PlannedReplication replication, ExperimentConfig config) {
        this.replication = replication;
        this.kind = config.budget();
        this.candidateLimit = config.candidateLimit();
        this.tickBudget = config.tickBudget();
        this.target = kind == BudgetKind.FIXED_TICKS ? java.util.Optional.of(config.target()) : java.util.Optional.empty();
        this.shared = new SharedMaps(replication.index());
        this.driversLeft = new AtomicInteger(config.drivers().size());
    }

    PlannedReplication replication() {
        return replication;
    }

    /** What the replication's drivers share: the maps judged so far and the situation names claimed. */
    SharedMaps shared() {
        return shared;
    }

    /** Whether the driver at {@code driverIndex} in the preset's order leads the replication. */
    boolean leads(int driverIndex) {
        // a campaign's trial has no leader: every driver gets the same fixed ticks
        return driverIndex == 0 && kind != BudgetKind.FIXED_TICKS;
    }

    /** The budget of the driver at {@code driverIndex}. */
    Budget budget(int driverIndex) {
        if (leads(driverIndex)) {
            return new Budget.Candidates(replication.candidates(), lead);
        }
        return switch (kind) {
            case TICKS -> new Budget.TicksOfLead(lead, candidateLimit);
            case WALL_CLOCK -> new Budget.WallClockOfLead(lead, candidateLimit);
            case FIXED_TICKS -> new Budget.FixedTicks(tickBudget, candidateLimit, target.orElseThrow());
        };
    }

    /** The driver stopped without finishing (a halt or a failure); if it led, nobody waits for it any more. */
    void failed(int driverIndex) {
        if (leads(driverIndex)) {
            lead.abandoned();
        }
    }

    /** The driver finished, having spent what {@code done} says; if it led, its followers learn their budget's end. */
    void finished(int driverIndex, Journal.Finished done) {
        if (leads(driverIndex)) {
            lead.finished(done.spend().ticks(), done.driverNanos());
        }
    }

    /**
     * Counts a driver off once everything about it was told; returns whether it was the replication's
     * last, so the replication's end is told after every driver's.
     */
    boolean countOff() {
        return driversLeft.decrementAndGet() == 0;
    }
}
