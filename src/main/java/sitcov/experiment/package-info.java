/**
 * The experiment engine: what an experiment is ({@link sitcov.experiment.ExperimentConfig}, read from a
 * preset, with the {@link sitcov.experiment.AnalysisPlan} it declares before any result exists and the
 * {@link sitcov.experiment.Measure}s a plan can name), its plan of replications and
 * {@link sitcov.experiment.Shard}s, where every seed comes from ({@link sitcov.experiment.SeedPlan}),
 * and the {@link sitcov.experiment.ExperimentRunner} that runs the replications. Each replication's
 * lead/follow protocol is its {@link sitcov.experiment.ReplicationPlan}: who leads, each driver's
 * {@link sitcov.experiment.Budget} (the leader's candidates; a follower's ticks or wall-clock time of the
 * leader, learnt from the {@link sitcov.experiment.Lead}), the maps the drivers share and the countdown
 * to the replication's end. Each driver's {@link sitcov.experiment.DriverSession} draws candidates and
 * charges what it spends; a {@link sitcov.experiment.SessionJudge} judges its maps, now
 * ({@link sitcov.experiment.FreshJudge}) or from a resumed run's {@link sitcov.experiment.Journal}
 * ({@link sitcov.experiment.JournalReplay}); the {@link sitcov.experiment.ExperimentEvent}s go to its
 * listeners. What it records of each map is a {@link sitcov.experiment.MapRun}; of each driver a
 * {@link sitcov.experiment.DriverRun}.
 *
 * <p>Drivers plug in through {@link sitcov.experiment.Driver} and {@link sitcov.experiment.DriverFactory}
 * (the ones sitcov ships are in {@code sitcov.drivers}). Knows no file format: the command line
 * attaches the listeners that write results ({@code sitcov.report}).
 */
package sitcov.experiment;
