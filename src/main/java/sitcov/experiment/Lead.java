package sitcov.experiment;

/**
 * The first driver's spend in a replication as it grows, for the later drivers of the replication,
 * which run beside it rather than after it. A later driver under the ticks budget may draw again
 * for certain while it has spent fewer ticks than the first has so far (the first's total can only
 * be more), and otherwise waits for the first to spend more or to finish: so it stops exactly where
 * it would have stopped running after the first, whatever the threads. Under the wall-clock budget
 * it runs on while the first runs, then until its own time reaches the first's.
 */
final class Lead {
    /** How long a waiting driver sleeps between looks at whether the run was halted. */
    private static final long HALT_CHECK_MILLIS = 100;

    private long ticks;
    private boolean finished;
    private boolean abandoned;
    private long finalNanos;

    /** The first driver has now spent {@code soFar} ticks. */
    synchronized void spent(long soFar) {
        ticks = soFar;
        notifyAll();
    }

    /** The first driver finished, having spent {@code total} ticks in {@code nanos} of its time. */
    synchronized void finished(long total, long nanos) {
        ticks = total;
        finalNanos = nanos;
        finished = true;
        notifyAll();
    }

    /** The first driver stopped without finishing (a halt or a failure): nobody waits for it any more. */
    synchronized void abandoned() {
        abandoned = true;
        notifyAll();
    }

    /** Whether a later driver that has spent {@code spent} ticks may draw another candidate; may wait. */
    synchronized boolean ticksLeft(long spent, Runnable checkHalt) {
        while (!finished && !abandoned && spent >= ticks) {
            try {
                wait(HALT_CHECK_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while waiting for the replication's first driver", e);
            }
            checkHalt.run();
        }
        checkAbandoned();
        return !finished || spent < ticks;
    }

    /** Whether a later driver that has run {@code elapsed} nanoseconds may draw another candidate. */
    synchronized boolean nanosLeft(long elapsed) {
        checkAbandoned();
        return !finished || elapsed < finalNanos;
    }

    /** The ticks the first driver has spent so far (for progress displays). */
    synchronized long ticksSoFar() {
        return ticks;
    }

    /** The first driver's wall time: its total once finished, else {@code nanosNow} (for progress displays). */
    synchronized long nanosSoFar(long nanosNow) {
        return finished ? finalNanos : nanosNow;
    }

    private void checkAbandoned() {
        if (abandoned && !finished) {
            throw new IllegalStateException("the replication's first driver stopped before it finished");
        }
    }
}
