package sitcov.control;

/**
 * Where an experiment's worker threads get their controller: each thread asks for its own factory
 * (a controller program runs one process per thread, reused across runs). Closing ends them all.
 */
public interface ControllerSource extends AutoCloseable {
    /** The factory of the calling thread. */
    ControllerFactory forThisThread();

    /** What it tests, as a preset names it ({@code builtin}, {@code exec:COMMAND ARGS…}). */
    String spec();

    @Override
    default void close() {
    }

    /** This source with every run run whole, never forked from a checkpoint ({@code --fork off}). */
    default ControllerSource unforked() {
        ControllerSource forked = this;
        return new ControllerSource() {
            @Override
            public ControllerFactory forThisThread() {
                return forked.forThisThread().unforked();
            }

            @Override
            public String spec() {
                return forked.spec();
            }

            @Override
            public void close() {
                forked.close();
            }
        };
    }
}
