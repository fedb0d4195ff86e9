/**
 * The experiment engine: what an experiment is ({@link sitcov.experiment.ExperimentConfig}, read from a
 * preset, with the {@link sitcov.experiment.AnalysisPlan} it declares before any result exists and the
 * {@link sitcov.experiment.Measure}s a plan can name), its plan of replications and
 * {@link sitcov.experiment.Shard}s, where every seed comes from ({@link sitcov.experiment.SeedPlan}),
 * and the {@link sitcov.experiment.ExperimentRunner} that runs the replications: the first driver's
 * {@link sitcov.experiment.Budget} of candidates, the later drivers' equal budget learnt from the
 * {@link sitcov.experiment.Lead}, each driver's {@link sitcov.experiment.DriverSession} (candidates,
 * judged maps shared within a replication, a resumed run's {@link sitcov.experiment.Journal} replayed)
 * and the {@link sitcov.experiment.ExperimentEvent}s it tells its listeners. What it records of each
 * map is a {@link sitcov.experiment.MapRun}; of each driver a {@link sitcov.experiment.DriverRun}.
 *
 * <p>Drivers plug in through {@link sitcov.experiment.Driver} and {@link sitcov.experiment.DriverFactory}
 * (the ones sitcov ships are in {@code sitcov.drivers}). Knows no file format: the command line
 * attaches the listeners that write results ({@code sitcov.report}).
 */
package sitcov.experiment;
