/**
 * Experiments: single runs ({@link sitcov.experiment.Simulator}), the differential fault oracle,
 * test drivers, budgets, replications and metrics. Knows no file format: reports are attached by
 * the command line.
 */
package sitcov.experiment;
