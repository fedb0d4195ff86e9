package sitcov.analysis;

import sitcov.experiment.Measure;
import sitcov.stats.EffectSize;

/**
 * One measure of one pair of drivers (A the earlier in the preset): the paired difference, the
 * equivalence test against the measure's margin (TOST p as tested and adjusted, and its 90 % t
 * interval), the unpaired Mann-Whitney p and Vargha–Delaney Â12 as description (the paired effect size is
 * {@link PairedDifference#superiority()}), and the finding;
 * {@code note} says why a measure was not tested. NaN marks what was not computed.
 */
public record MeasureComparison(Measure measure, String driverA, String driverB, boolean primary,
                                PairedDifference paired, double margin, double pTost, double pTostAdjusted,
                                double tostLow, double tostHigh, double pMannWhitney, double a12, EffectSize effect,
                                Finding finding, String note) {
}
