package sitcov.estimate;

import sitcov.world.Tilt;

/**
 * The proposal a stage of a replication drew its maps under, and how it was fitted: the score level
 * of the elite it was refitted to and that elite's size (NaN and 0 for the generator itself).
 */
public record ProposalRow(int replication, String stage, double level, int elite, Tilt tilt) {
}
