/**
 * Experiments: single runs ({@link sitcov.experiment.Simulator}), a map judged under every fault
 * ({@link sitcov.experiment.MapRunner}), the differential oracle, the {@link sitcov.experiment.Driver}
 * extension point and its drivers, budgets, the {@link sitcov.experiment.ExperimentRunner} and the
 * events it emits, the {@link sitcov.experiment.SeedPlan}, the paper's measures and the
 * {@link sitcov.experiment.Comparison} of drivers that a declared {@link sitcov.experiment.AnalysisPlan}
 * judges (a primary question, one exploratory family, equivalence margins). Knows no file
 * format: the command line attaches the listeners that write results.
 */
package sitcov.experiment;
