/**
 * Judging one map: a run of the car through it ({@link sitcov.judge.Simulator}, stepped a tick at a
 * time by {@link sitcov.judge.LiveRun}, watched by a {@link sitcov.judge.RunObserver}), its fault-free
 * run and one faulty twin per fault ({@link sitcov.judge.MapRunner}), and the verdict on each fault
 * from the differential oracle ({@link sitcov.judge.DifferentialOracle}, settled as it happens by
 * {@link sitcov.judge.VerdictWatch}) or the paper's notion: {@link sitcov.judge.FaultVerdict}, kept by
 * an experiment as {@link sitcov.judge.FaultOutcome} and {@link sitcov.judge.RunSummary}. Fault
 * calibration ({@link sitcov.judge.FaultCalibration}) judges many maps this way. A variant that is
 * another controller ({@link sitcov.judge.Variant}) is judged against the reference the same way. A faulty
 * run of a controller that can be copied is forked from a checkpoint of the fault-free run where its
 * fault first departs, or judged from it if it never does ({@link sitcov.judge.ForkedRuns}); a run
 * stepped back uses the same checkpoints ({@link sitcov.judge.RunHistory}). A new way to run or
 * judge a map starts here; nothing here knows experiments, drivers or files.
 */
package sitcov.judge;
