package sitcov.control;

/**
 * A controller whose command is worked out elsewhere, together with other runs' (a controller
 * program answering a batch of runs in one message). The world hands it the observation with
 * {@link #observe} and pauses the run's tick there; once every run of the batch has observed, one
 * exchange answers them all, the tick resumes, and {@link #step} fills in the command answered to
 * that same observation. Nothing moves between the two calls, so the run is the run it would have
 * been with a controller that answered at once.
 */
public interface DeferredController extends Controller {
    /** Takes this tick's observation; its command is handed over by the {@link #step} that follows. */
    void observe(Observation now);
}
