/**
 * Statistics as pure functions of numbers: no other sitcov package is used here.
 *
 * <p>Besides {@link sitcov.stats.Richness}, the package holds what comparing configurations over
 * replicated runs needs: the rank tests {@link sitcov.stats.MannWhitney} and
 * {@link sitcov.stats.WilcoxonSignedRank} with the effect size {@link sitcov.stats.VarghaDelaney},
 * {@link sitcov.stats.FisherExact} for proportions of runs with an odds ratio, {@link sitcov.stats.Holm},
 * {@link sitcov.stats.ClosedTesting} and {@link sitcov.stats.BenjaminiHochberg} for families of tests, {@link sitcov.stats.Tost} for equivalence within a margin (on
 * {@link sitcov.stats.StudentT}), {@link sitcov.stats.DetectableDifference} for what a test could have
 * found, {@link sitcov.stats.Dispersion} for how clustered binomial counts are, {@link sitcov.stats.Wilson} intervals for a proportion and
 * {@link sitcov.stats.Bootstrap} intervals for a difference of means, on top of
 * {@link sitcov.stats.Normal}, {@link sitcov.stats.Ranks} and {@link sitcov.stats.Descriptive}.
 * Tests are two-sided and follow R's defaults where R has one, so that any figure can be checked
 * there; every randomised method takes its generator from the caller.
 */
package sitcov.stats;
