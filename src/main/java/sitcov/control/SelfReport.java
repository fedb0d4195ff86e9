package sitcov.control;

import sitcov.geom.Compass;

/**
 * What a controller may say about itself in a tick: which manoeuvre it believes it is in and which
 * behaviour set its speed and steering. Kept in the telemetry for people reading a run; the oracle
 * never judges by it (experiments/controllers/README.md, "What the oracle judges").
 */
public final class SelfReport {
    private boolean overtaking;
    private boolean crossingJunction;
    private boolean waitingAtJunction;
    private Compass lane;
    private String stage;
    private String limitedBy;
    private String steeredBy;

    void clear() {
        overtaking = false;
        crossingJunction = false;
        waitingAtJunction = false;
        lane = null;
        stage = null;
        limitedBy = null;
        steeredBy = null;
    }

    public SelfReport overtaking(boolean on) {
        overtaking = on;
        return this;
    }

    public SelfReport crossingJunction(boolean on) {
        crossingJunction = on;
        return this;
    }

    public SelfReport waitingAtJunction(boolean on) {
        waitingAtJunction = on;
        return this;
    }

    public SelfReport lane(Compass direction) {
        lane = direction;
        return this;
    }

    /** The stage of its manoeuvre, by its own name (the builtin car's overtaking stages). */
    public SelfReport stage(String name) {
        stage = name;
        return this;
    }

    public SelfReport limitedBy(String behaviour) {
        limitedBy = behaviour;
        return this;
    }

    public SelfReport steeredBy(String behaviour) {
        steeredBy = behaviour;
        return this;
    }

    public boolean overtaking() {
        return overtaking;
    }

    public boolean crossingJunction() {
        return crossingJunction;
    }

    public boolean waitingAtJunction() {
        return waitingAtJunction;
    }

    /** The lane direction it believes it drives, or null. */
    public Compass lane() {
        return lane;
    }

    /** The stage of its manoeuvre, or null. */
    public String stage() {
        return stage;
    }

    /** The behaviour that set the speed limit, or null. */
    public String limitedBy() {
        return limitedBy;
    }

    /** The behaviour that steered, or null. */
    public String steeredBy() {
        return steeredBy;
    }

    /** Copies {@code other} into this one. */
    public void copyOf(SelfReport other) {
        overtaking = other.overtaking;
        crossingJunction = other.crossingJunction;
        waitingAtJunction = other.waitingAtJunction;
        lane = other.lane;
        stage = other.stage;
        limitedBy = other.limitedBy;
        steeredBy = other.steeredBy;
    }
}
