package sitcov.oracle;

import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import sitcov.control.ControllerFailure;
import sitcov.control.Vehicle;
import sitcov.engine.SimState;
import sitcov.engine.Steppable;
import sitcov.geom.Box;
import sitcov.vehicles.Dynamics;
import sitcov.vehicles.Telemetry;

/**
 * The accident oracle, stepped every tick after all vehicles moved. Each accident is an event:
 * it is recorded when the car enters the state (a new overlap, going off the road, crossing the
 * centre line), not again while the state lasts. It also ends the run: when the car reaches the
 * Target, or with a TIMEOUT event after 5000 ticks. Accidents are judged from what anyone sees of
 * the car — its footprint, pose and speed against the map and the other vehicles ({@link CentreLineExcuse},
 * {@link BlameRules}); only the end at the Target still takes the car's word.
 */
public final class AccidentDetector implements Steppable {
    /** After every vehicle has moved. */
    public static final int ORDERING = 1;

    private Telemetry run;
    private boolean[] touchingParked;
    private boolean[] touchingMoving;
    private List<Accident> accidents = new ArrayList<>();
    private Map<Blame, Integer> excused = new EnumMap<>(Blame.class);
    private List<ExcusedContact> excusedContacts = new ArrayList<>();
    private CentreLine centreLine;
    private CentreLineExcuse centreLineExcuse;
    private boolean offRoad;
    private boolean overCentreLine;
    private Outcome outcome;
    private long ticks;

    public AccidentDetector(Telemetry run) {
        this.run = run;
        this.touchingParked = new boolean[run.parkedBodies().size()];
        this.touchingMoving = new boolean[run.movingCars().size()];
        this.centreLine = new CentreLine(run.network());
        this.centreLineExcuse = new CentreLineExcuse(run.network(), run.map().layout().parkedCars());
    }

    @Override
    public void step(SimState state) {
        Vehicle car = run.car();
        long tick = state.tick();
        Box body = car.footprint();
        List<Box> parked = run.parkedBodies();
        double reach = circumradius(body.length(), body.width());
        for (int i = 0; i < parked.size(); i++) {
            Box other = parked.get(i);
            boolean touching = !apart(body.centreX(), body.centreY(), reach, other.centreX(), other.centreY(),
                    circumradius(other.length(), other.width())) && body.overlaps(other);
            if (touching && !touchingParked[i]) {
                record(tick, AccidentType.CLASHWITHOBSTACLE, car, i);
            }
            touchingParked[i] = touching;
        }
        boolean off = !run.network().isOnRoad(body);
        if (off && !offRoad) {
            record(tick, AccidentType.LEAVEROAD, car, -1);
        }
        offRoad = off;
        boolean over = centreLine.isOver(body, car.headingDx(), car.headingDy());
        // the excuse is judged from the footprint and the map, never from what the car says it is doing
        boolean unexcused = over && !centreLineExcuse.applies(body);
        if (unexcused && !overCentreLine) {
            record(tick, AccidentType.CROSSCENTRELINE, car, -1);
        }
        overCentreLine = unexcused;
        List<? extends Vehicle> moving = run.movingCars();
        for (int i = 0; i < moving.size(); i++) {
            Vehicle other = moving.get(i);
            boolean touching = other.isActive() && !apart(body.centreX(), body.centreY(), reach,
                    other.x() - other.length() / 2 * other.headingDx(), other.y() - other.length() / 2 * other.headingDy(),
                    circumradius(other.length(), other.width()))
                    && body.overlaps(other.footprint());
            if (touching && !touchingMoving[i]) {
                Blame blame = BlameRules.judge(car, other, centreLine, over);
                if (blame.isAccident()) {
                    record(tick, AccidentType.CLASHWITHOTHERCAR, car, other.id());
                } else {
                    excused.merge(blame, 1, Integer::sum);
                    excusedContacts.add(new ExcusedContact(tick, blame, car.x(), car.y(), other.id()));
                }
            }
            touchingMoving[i] = touching;
        }
        if (run.failure() != null) {
            finish(state, run.failure().kind() == ControllerFailure.Kind.TIMEOUT
                    ? Outcome.CONTROLLER_TIMEOUT : Outcome.CONTROLLER_ERROR, tick);
        } else if (run.reachedTarget()) {
            finish(state, Outcome.TARGET_REACHED, tick);
        } else if (tick + 1 >= Dynamics.TIMEOUT_TICKS) {
            record(tick, AccidentType.TIMEOUT, car, -1);
            finish(state, Outcome.TIMEOUT, tick);
        }
    }

    /**
     * Whether two boxes, by their centres and the radii of the circles round them, are certainly
     * apart: their circles are, by a margin far beyond rounding, so no overlap test would find them
     * touching. Spares the footprint and the separating-axis test of everyone not near the car.
     */
    private static boolean apart(double ax, double ay, double aReach, double bx, double by, double bReach) {
        double dx = bx - ax;
        double dy = by - ay;
        double beyond = aReach + bReach + 1e-6;
        return dx * dx + dy * dy > beyond * beyond;
    }

    private static double circumradius(double length, double width) {
        return Math.sqrt(length * length + width * width) / 2;
    }

    private void record(long tick, AccidentType type, Vehicle car, int other) {
        accidents.add(new Accident(tick, type, car.x(), car.y(), other));
    }

    private void finish(SimState state, Outcome how, long tick) {
        outcome = how;
        ticks = tick + 1;
        state.schedule().clear();
    }

    /** Ends the run after the current tick, its verdict settled (only an experiment's faulty runs are stopped). */
    public void stopAtVerdict(SimState state) {
        if (outcome == null) {
            finish(state, Outcome.STOPPED_AT_VERDICT, state.tick());
        }
    }

    /** How many accidents so far (cheaper than {@link #accidents()} when polled every tick). */
    public int accidentCount() {
        return accidents.size();
    }

    /** Accidents so far, in the order they happened. */
    public List<Accident> accidents() {
        return Collections.unmodifiableList(accidents);
    }

    /** How the run ended, or null while it goes on. */
    public Outcome outcome() {
        return outcome;
    }

    public long ticks() {
        return ticks;
    }

    public Map<Blame, Integer> excusedContacts() {
        return excused;
    }

    /** The excused contacts so far, each as it began, in the order they began. */
    public List<ExcusedContact> excusedContactEvents() {
        return Collections.unmodifiableList(excusedContacts);
    }
}
