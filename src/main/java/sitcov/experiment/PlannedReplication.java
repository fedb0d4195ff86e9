package sitcov.experiment;

/**
 * One replication of an experiment's plan: its index (the {@code replication} column of the
 * results), the label its candidate stream derives from, the first driver's candidate budget, and
 * for a sweep the budget and map set it stands for ({@code sweepBudget} 0 in a comparison).
 */
public record PlannedReplication(int index, String streamLabel, int candidates, int sweepBudget, int set) {
}
