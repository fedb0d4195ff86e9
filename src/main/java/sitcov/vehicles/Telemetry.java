package sitcov.vehicles;

import java.util.List;
import sitcov.control.ControllerFailure;
import sitcov.control.Observation;
import sitcov.control.SelfReport;
import sitcov.control.Vehicle;
import sitcov.geom.Box;
import sitcov.world.RoadNetwork;
import sitcov.world.WorldMap;

/**
 * One tick of a run as its watchers receive it — the accident oracle, trace and trajectory
 * recorders, replays and the viewer: the car under test's pose, footprint and speed, the command
 * the world carried out (after clamping), the controller's self-report (information only), and the
 * other vehicles as anyone may observe them. A read-only view, refreshed each tick rather than
 * copied, so that watching costs no allocation; a watcher that keeps anything copies the values.
 * Nothing here can change the run.
 */
public interface Telemetry {
    long tick();

    WorldMap map();

    RoadNetwork network();

    /** Parked-car footprints, in parked-car order. */
    List<Box> parkedBodies();

    /** The car under test: pose, footprint, speed. */
    Vehicle car();

    /** The speed change and steering the world carried out this tick, after clamping. */
    double speedChange();

    double steering();

    /** Whether this tick's command asked for more than the car's limits. */
    boolean clamped();

    /** What the world clamped in this tick's command (asked and given), or null when nothing. */
    String clampNote();

    /** How many ticks' commands the world clamped so far in the run. */
    long clampedTicks();

    /**
     * What the world offers the car's controller this tick, whatever controller it is: among the rest,
     * the standard camera's and LIDAR's hits, which a viewer draws (worked out when first asked for).
     */
    Observation observation();

    /** The sensors whose parts of {@link #observation} the car's controller takes (a replay: the recorded run's). */
    java.util.Set<sitcov.control.Sensor> sensors();

    /** What the controller said of itself this tick: kept for people, never judged by. */
    SelfReport selfReport();

    /** Every moving car, active or not, in id order. */
    List<? extends Vehicle> movingCars();

    /** Whether the car's front now stands on the Target (judged by the world from geometry). */
    boolean reachedTarget();

    /** Why the controller gave no command, once it failed; null while it works. */
    ControllerFailure failure();
}
