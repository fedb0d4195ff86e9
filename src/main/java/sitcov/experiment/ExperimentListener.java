package sitcov.experiment;

/**
 * Receives an experiment's events; the command line attaches listeners that write the results
 * folder and show progress, so the runner knows no file format. Events arrive one at a time
 * (never concurrently), from the runner's worker threads.
 */
@FunctionalInterface
public interface ExperimentListener {
    void on(ExperimentEvent event);
}
