package sitcov.vehicles;

import sitcov.control.Command;
import sitcov.control.Controller;
import sitcov.control.ControllerFailure;
import sitcov.control.DeferredController;
import sitcov.control.Observation;
import sitcov.control.SelfReport;
import sitcov.control.Vehicle;
import sitcov.engine.SimState;
import sitcov.engine.Steppable;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.world.Dimensions;
import sitcov.world.StartPose;

/**
 * The car under test as the world has it: a body that only the world moves. Each tick, at its turn
 * among the vehicles (shuffled every tick, as every agent of one ordering is), it hands its
 * controller an observation, takes back a command, carries out the
 * command's right-of-way requests, clamps its speed change and steering to the car's limits
 * (recording that it had to), turns, moves, and judges from the geometry whether the car now
 * stands on the Target. The controller's self-report is kept for people, never judged by.
 */
public final class AutonomousCar implements Bodied, Steppable {
    public static final int ID = 0;
    /** Its rear axle, which it turns about, is this far behind its front. */
    public static final double REAR_AXLE = 1.5;
    /** Ticks after which another vehicle's hold on a junction is stale, and the car under test is given it. */
    static final long PATIENCE = 30;

    private Scene scene;
    private Body body;
    private Controller controller;
    private SceneObservation observation;
    private Command command = new Command();
    private SelfReport report = new SelfReport();
    private TargetArrival arrival;
    private double speedChange;
    private double steering;
    private boolean clamped;
    private long clampedTicks;
    private double askedSpeed;
    private double askedSteering;
    private boolean reachedTarget;
    /** Its deferred controller has the tick's observation; the tick is paused until its command is in. */
    private boolean awaitingCommand;
    private ControllerFailure failure;
    private Box keptClear;
    private Box keptClearOf;
    private CommandLog log = new CommandLog();

    AutonomousCar(Scene scene, StartPose start, Controller controller) {
        this.scene = scene;
        this.body = new Body(start.position().x(), start.position().y(), start.heading().bearing(), REAR_AXLE);
        this.controller = controller;
        this.observation = new SceneObservation(scene, this);
        this.arrival = new TargetArrival(scene.target());
        log.sensors(controller.sensors());
    }

    /** The sensors its controller takes. */
    java.util.Set<sitcov.control.Sensor> sensors() {
        return log.sensors();
    }

    @Override
    public void step(SimState state) {
        if (reachedTarget || failure != null) {
            return;
        }
        if (awaitingCommand) {
            awaitingCommand = false;
        } else {
            observation.refresh(state.tick());
            if (controller instanceof DeferredController deferred && observed(deferred)) {
                // the tick resumes, and this step comes again, once the command is in
                awaitingCommand = true;
                state.schedule().pause();
                return;
            }
        }
        if (failure != null) {
            return;
        }
        command.clear();
        try {
            controller.step(observation, command);
        } catch (ControllerFailure failed) {
            failure = failed;
            log.failed(failed.kind(), failed.getMessage());
            return;
        } catch (RuntimeException bug) {
            // a controller in process that throws has crashed, as a program that exits has: the run ends in its failure
            failure = new ControllerFailure(ControllerFailure.Kind.ERROR, "the controller threw " + bug);
            log.failed(failure.kind(), failure.getMessage());
            return;
        }
        report.copyOf(command.report());
        logRequests();
        String broken = brokenJunctionRule();
        if (broken != null) {
            // logged as asked: played again, the same requests break the same rule
            log.command(command.speed(), command.steering());
            failure = new ControllerFailure(ControllerFailure.Kind.ERROR, "the controller broke the world's rules: " + broken);
            return;
        }
        grantRightOfWay(state.tick());
        drive();
        log.command(body.speed(), steering);
        if (clamped) {
            log.clamped(askedSpeed, askedSteering);
        }
        reachedTarget = arrival.isReached(body.x(), body.y());
    }

    private void logRequests() {
        log.report(report);
        for (int i = 0; i < command.releaseCount(); i++) {
            log.release(command.releaseAt(i));
        }
        for (int i = 0; i < command.claimCount(); i++) {
            log.claim(command.claimAt(i));
        }
    }

    /** The commands the world carried out so far in the run. */
    public CommandLog commandLog() {
        return log;
    }

    /** Hands the observation to a controller that answers later; false when it failed at once (the run then ends). */
    private boolean observed(DeferredController deferred) {
        try {
            deferred.observe(observation);
            return true;
        } catch (ControllerFailure failed) {
            failure = failed;
        } catch (RuntimeException bug) {
            failure = new ControllerFailure(ControllerFailure.Kind.ERROR, "the controller threw " + bug);
        }
        log.failed(failure.kind(), failure.getMessage());
        return false;
    }

    /**
     * The junction rule the command breaks, or null (experiments/controllers/README.md, "How the car moves"): it
     * names only
     * junctions of the map; it claims a junction only within {@link JunctionRules#CLAIM_WITHIN} of
     * its square; after its releases it holds and asks for at most {@link JunctionRules#MAX_HELD}.
     */
    private String brokenJunctionRule() {
        int junctions = scene.network().junctions().size();
        for (int i = 0; i < command.releaseCount(); i++) {
            int j = command.releaseAt(i);
            if (j < 0 || j >= junctions) {
                return "it released junction " + j + ", which the map does not have (its junctions are 0.." + (junctions - 1) + ")";
            }
        }
        if (command.claimCount() == 0) {
            return null;
        }
        for (int i = 0; i < command.claimCount(); i++) {
            int j = command.claimAt(i);
            if (j < 0 || j >= junctions) {
                return "it claimed junction " + j + ", which the map does not have (its junctions are 0.." + (junctions - 1) + ")";
            }
            double d = distanceToSquare(scene.network().junctions().get(j).square());
            if (d > JunctionRules.CLAIM_WITHIN) {
                return String.format(java.util.Locale.ROOT, "it claimed junction %d %.1f m from its square; a junction may be"
                        + " claimed only within %.0f m of its square", j, d, JunctionRules.CLAIM_WITHIN);
            }
        }
        JunctionOccupancy occupancy = scene.occupancy();
        int wanted = 0;
        StringBuilder which = new StringBuilder();
        for (int j = 0; j < junctions; j++) {
            boolean released = false;
            for (int i = 0; i < command.releaseCount() && !released; i++) {
                released = command.releaseAt(i) == j;
            }
            boolean claimed = false;
            for (int i = 0; i < command.claimCount() && !claimed; i++) {
                claimed = command.claimAt(i) == j;
            }
            if (claimed || occupancy.isHeldBy(j, ID) && !released) {
                wanted++;
                which.append(which.length() == 0 ? "" : ", ").append(j).append(claimed ? " claimed" : " held");
            }
        }
        if (wanted > JunctionRules.MAX_HELD) {
            return "after its releases it held and claimed " + wanted + " junctions (" + which + "); a car may hold at most "
                    + JunctionRules.MAX_HELD + " at once";
        }
        return null;
    }

    /** How far the car's front centre is from {@code square} (0 inside it). */
    private double distanceToSquare(sitcov.geom.Rect square) {
        double dx = Math.max(0, Math.max(square.minX() - body.x(), body.x() - square.maxX()));
        double dy = Math.max(0, Math.max(square.minY() - body.y(), body.y() - square.maxY()));
        return Math.hypot(dx, dy);
    }

    /** Lets go first, then asks: a junction asked for is given when the signal showed it would be. */
    private void grantRightOfWay(long tick) {
        JunctionOccupancy occupancy = scene.occupancy();
        for (int i = 0; i < command.releaseCount(); i++) {
            int j = command.releaseAt(i);
            occupancy.release(j, ID);
        }
        for (int i = 0; i < command.claimCount(); i++) {
            int j = command.claimAt(i);
            if (!scene.isOccupiedByOther(scene.network().junctions().get(j), this)) {
                occupancy.request(j, ID, tick, PATIENCE);
            }
        }
    }

    private void drive() {
        double wanted = Double.isNaN(command.speed()) ? body.speed() + command.speedChange() : command.speed();
        double speed = Math.max(0, Math.min(Dynamics.MAX_SPEED, Double.isNaN(wanted) ? body.speed() : wanted));
        double turn = command.steering();
        double allowed = Double.isNaN(turn) ? 0 : Math.max(-Dynamics.MAX_TURN, Math.min(Dynamics.MAX_TURN, turn));
        clamped = speed != wanted || allowed != turn;
        askedSpeed = wanted;
        askedSteering = turn;
        if (clamped) {
            clampedTicks++;
        }
        speedChange = speed - body.speed();
        steering = allowed;
        body.setSpeed(speed);
        body.turnBy(allowed);
        body.move();
    }

    /** The run is over: the controller is told how it ended. */
    public void end(String outcome, long ticks) {
        controller.end(new sitcov.control.RunEnd(outcome, ticks));
    }

    /** Why the controller gave no command, once it failed (the run then ends); null while it works. */
    public ControllerFailure failure() {
        return failure;
    }

    public Controller controller() {
        return controller;
    }

    /** Whether its front stands on the Target, in the Target's lane (the run is then over). */
    public boolean hasReachedTarget() {
        return reachedTarget;
    }

    /** What the car observes: refreshed at the start of each tick, before its controller steps. */
    Observation observation() {
        return observation;
    }

    /** What the controller said of itself in the last tick: information only. */
    public SelfReport selfReport() {
        return report;
    }

    /** The speed change and steering the world carried out in the last tick, after clamping. */
    public double appliedSpeedChange() {
        return speedChange;
    }

    public double appliedSteering() {
        return steering;
    }

    /** Whether the last command asked for more than the car's limits; how many ticks did so far. */
    public boolean wasClamped() {
        return clamped;
    }

    public long clampedTicks() {
        return clampedTicks;
    }

    /**
     * What the world clamped in the last command, e.g. {@code speed asked 3.1000 given 2.5000}
     * (speeds in metres a tick, steering in degrees, 4 decimals); null when it clamped nothing.
     */
    public String clampNote() {
        if (!clamped) {
            return null;
        }
        StringBuilder note = new StringBuilder();
        if (askedSpeed != body.speed()) {
            note.append(String.format(java.util.Locale.ROOT, "speed asked %.4f given %.4f", askedSpeed, body.speed()));
        }
        if (askedSteering != steering) {
            note.append(note.length() == 0 ? "" : "; ").append(String.format(java.util.Locale.ROOT,
                    "steering asked %.4f given %.4f", askedSteering, steering));
        }
        return note.toString();
    }

    /** Its footprint grown by {@link Clearance#AROUND_THE_CAR} all round: where traffic keeps out. */
    Box keptClear() {
        Box now = footprint();
        if (keptClearOf != now) {
            double h = body.heading();
            keptClear = Box.behind(body.x() + Clearance.AROUND_THE_CAR * Bearing.dx(h),
                    body.y() + Clearance.AROUND_THE_CAR * Bearing.dy(h), h,
                    length() + 2 * Clearance.AROUND_THE_CAR, width() + 2 * Clearance.AROUND_THE_CAR);
            keptClearOf = now;
        }
        return keptClear;
    }

    @Override
    public int id() {
        return ID;
    }

    @Override
    public double length() {
        return Dimensions.AUTONOMOUS_CAR_LENGTH;
    }

    @Override
    public double width() {
        return Dimensions.AUTONOMOUS_CAR_WIDTH;
    }

    @Override
    public boolean isActive() {
        return true;
    }

    @Override
    public Body body() {
        return body;
    }
}
