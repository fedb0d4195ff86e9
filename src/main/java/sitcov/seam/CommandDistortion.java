package sitcov.seam;

import sitcov.control.Observation;

/**
 * A seam fault of the command: between the controller and the world it changes the motion the
 * controller asked for into the motion the world gets. It sees the real observation (the car's true
 * speed, as an actuator would act on it) and is told what the world carried out.
 */
abstract non-sealed class CommandDistortion implements Distortion {
    protected long tick;

    @Override
    public void startTick(Observation real, long t) {
        tick = t;
        started();
    }

    /** Called once {@link #tick} is this tick's. */
    void started() {
    }

    @Override
    public boolean acting() {
        return true;
    }

    /** Fills {@code given}, what the world gets, from {@code asked}, what the controller asked for. */
    abstract void distort(Motion asked, Observation real, Motion given);

    /** What the world was handed this tick (the distorted motion where the fault acts, else the asked one). */
    void handed(Motion motion) {
    }
}
