package sitcov.seam;

/** What a seam fault switched on did in one run: reached, how many ticks it was effective, and the first. */
public record SeamActivation(SeamFault fault, boolean reached, long effectiveCount, long firstEffectiveTick) {
}
