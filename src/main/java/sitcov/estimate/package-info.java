/**
 * How often a controller fails on the maps the generator stands for: the failure rate per
 * requirement and for any failure, estimated by plain Monte Carlo and by importance sampling under
 * a proposal a cross-entropy method tilts towards failures, with confidence intervals, effective
 * sample sizes and the ticks each spent (experiments/estimate.md).
 */
package sitcov.estimate;
