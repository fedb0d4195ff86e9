package sitcov.oracle;

import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import sitcov.control.Vehicle;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.BoxGap;
import sitcov.vehicles.Dynamics;
import sitcov.vehicles.Telemetry;
import sitcov.world.Junction;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;

/**
 * How close one run came to each accident: near-miss measures ({@link NearMiss}) and a robustness
 * ρ per accident type, watched from the same {@link Telemetry} as the {@link AccidentDetector}, with
 * the same footprints, the same road surface, the same centre line and {@link CentreLineExcuse} and
 * the same {@link BlameRules}. Call {@link #afterTick} once after every tick, the last one included
 * (a {@code RunObserver} is called then; an agent scheduled after the detector is not, once the
 * detector ends the run). Deterministic, and nothing is allocated per tick except the car's
 * footprint while it is over the centre line or begins a contact, which the detector's rules take.
 *
 * <p>Each measure is the least value over the ticks watched, with the first tick it was reached:
 * <ul>
 *   <li>{@link NearMiss#MOVING_GAP}, {@link NearMiss#PARKED_GAP}: {@link BoxGap#signedDistance} from the
 *       car's footprint to each active moving vehicle's, to each parked car's;</li>
 *   <li>{@link NearMiss#ROAD_EDGE}: {@link RoadEdges#margin}, the signed distance to the edge of the
 *       roads' surface;</li>
 *   <li>{@link NearMiss#CENTRE_LINE}: the least, over the footprint's corners outside junction squares
 *       and the roads holding them, of how far the corner is from the centre line on its own side (the
 *       lane the car's heading gives on that road, as {@link CentreLine} judges), negative on the other
 *       side; ticks over the line with an excuse ({@link CentreLineExcuse}) do not count;</li>
 *   <li>{@link NearMiss#TIME_TO_COLLISION}: each tick, for each active moving vehicle, the time in
 *       ticks until the two footprints would first touch if both kept this tick's velocity (speed in
 *       metres a tick along the heading) and heading ({@link BoxGap#timeToContact}, exact for boxes
 *       translating without turning, unbounded horizon); 0 while touching; infinite when their paths
 *       never meet so;</li>
 *   <li>{@link NearMiss#POST_ENCROACHMENT}: at each T-junction's square, when the car's footprint enters
 *       it (its interior overlaps the square) while a moving vehicle is out of it after having been in,
 *       the ticks since that vehicle left (the first tick it was out) — and the same with the two
 *       swapped. Entering while the other is still in does not count: traffic going the other way
 *       shares the square as a matter of course.</li>
 * </ul>
 * An unmet measure (no parked cars, never at a junction with traffic) stays infinite, tick −1.
 *
 * <p>Robustness, in signal temporal logic over the run's ticks t (□ "always"):
 * <ul>
 *   <li>CLASHWITHOBSTACLE: ρ(□ parkedGap &gt; 0) = min over t of PARKED_GAP(t);</li>
 *   <li>CLASHWITHOTHERCAR: ρ(□ (contact excused ∨ movingGap &gt; 0)) = min over t and active vehicles of
 *       the signed gap, leaving out a vehicle while its contact with the car is excused by
 *       {@link BlameRules} (judged when the contact begins, as the detector does);</li>
 *   <li>LEAVEROAD: ρ(□ roadEdge &gt; 0) = min over t of ROAD_EDGE(t);</li>
 *   <li>CROSSCENTRELINE: ρ(□ (excused ∨ centreLine &gt; 0)) = CENTRE_LINE;</li>
 *   <li>TIMEOUT: ρ(◇<sub>[0, 5000)</sub> atTarget) = 5000 − t for the tick t the Target was reached; 0
 *       when the run timed out; NaN while the run goes on or when it ended otherwise (a controller failure).</li>
 * </ul>
 * The detector counts an overlap or a centre-line crossing only beyond its 1e-9 m tolerance, so a run
 * with such an accident has ρ &lt; 0, and a run without one ρ &ge; −1e-9 (0 when merely touching).
 */
public final class NearMisses {
    /** The detector's tolerance ({@code Box}, {@code CentreLine}). */
    private static final double EPS = 1e-9;
    private static final double HALF_SQUARE = sitcov.world.Dimensions.JUNCTION_SIZE / 2;

    private double[] least = new double[NearMiss.values().length];
    private long[] leastTick = new long[NearMiss.values().length];
    private double otherCarRho = Double.POSITIVE_INFINITY;
    private double timeoutRho = Double.NaN;

    private RoadEdges roadEdges;
    private RoadNetwork network;
    private Road[] roads;
    private Junction[] junctions;
    private CentreLine centreLine;
    private CentreLineExcuse centreLineExcuse;

    // parked cars: centre, forward axis, half sizes
    private double[] parkedX;
    private double[] parkedY;
    private double[] parkedFx;
    private double[] parkedFy;
    private double[] parkedHl;
    private double[] parkedHw;

    private boolean[] touching;
    private boolean[] excused;

    // T-junction squares, and who is in them: the car, then moving vehicle i at [i * squares + j]
    private double[] squareX;
    private double[] squareY;
    private boolean[] carIn;
    /** Per square, whether the car entered it this tick (scratch for {@link #watchSquares}). */
    private boolean[] carEnters;
    private long[] carLeft;
    private boolean[] otherIn;
    /** Per moving vehicle, how many squares it is in ({@code otherIn}'s trues in its row). */
    private int[] inCount;
    private SquareGrid squareGrid;
    private long[] otherLeft;

    public NearMisses(Telemetry run) {
        Arrays.fill(least, Double.POSITIVE_INFINITY);
        Arrays.fill(leastTick, -1);
        this.roadEdges = new RoadEdges(run.network().surfaces());
        this.network = run.network();
        this.roads = run.network().roads().toArray(new Road[0]);
        this.junctions = run.network().junctions().toArray(new Junction[0]);
        this.centreLine = new CentreLine(run.network());
        this.centreLineExcuse = new CentreLineExcuse(run.network(), run.map().layout().parkedCars());
        List<Box> parked = run.parkedBodies();
        int n = parked.size();
        parkedX = new double[n];
        parkedY = new double[n];
        parkedFx = new double[n];
        parkedFy = new double[n];
        parkedHl = new double[n];
        parkedHw = new double[n];
        for (int i = 0; i < n; i++) {
            Box b = parked.get(i);
            parkedX[i] = b.centreX();
            parkedY[i] = b.centreY();
            parkedFx[i] = Bearing.dx(b.bearing());
            parkedFy[i] = Bearing.dy(b.bearing());
            parkedHl[i] = b.length() / 2;
            parkedHw[i] = b.width() / 2;
        }
        int moving = run.movingCars().size();
        touching = new boolean[moving];
        excused = new boolean[moving];
        List<Junction> tees = run.network().junctions().stream().filter(j -> !j.isDeadEnd()).toList();
        squareX = new double[tees.size()];
        squareY = new double[tees.size()];
        for (int j = 0; j < tees.size(); j++) {
            squareX[j] = tees.get(j).centre().x();
            squareY[j] = tees.get(j).centre().y();
        }
        carIn = new boolean[tees.size()];
        carEnters = new boolean[tees.size()];
        carLeft = new long[tees.size()];
        Arrays.fill(carLeft, -1);
        otherIn = new boolean[moving * tees.size()];
        inCount = new int[moving];
        squareGrid = new SquareGrid(squareX, squareY);
        otherLeft = new long[moving * tees.size()];
        Arrays.fill(otherLeft, -1);
    }

    /** Looks at the tick that just ran. */
    public void afterTick(Telemetry run) {
        long tick = run.tick();
        Vehicle car = run.car();
        // the car's footprint as Vehicle.footprint() makes it: anchored at the front centre
        double fx = Bearing.dx(car.heading());
        double fy = Bearing.dy(car.heading());
        double hl = car.length() / 2;
        double hw = car.width() / 2;
        double cx = car.x() - hl * fx;
        double cy = car.y() - hl * fy;
        double reach = Math.sqrt(hl * hl + hw * hw);

        for (int i = 0; i < parkedX.length; i++) {
            double px = parkedX[i] - cx;
            double py = parkedY[i] - cy;
            double bound = Math.sqrt(px * px + py * py) - reach
                    - Math.sqrt(parkedHl[i] * parkedHl[i] + parkedHw[i] * parkedHw[i]);
            if (bound < least[NearMiss.PARKED_GAP.ordinal()]) {
                keep(NearMiss.PARKED_GAP, BoxGap.signedDistance(cx, cy, fx, fy, hl, hw,
                        parkedX[i], parkedY[i], parkedFx[i], parkedFy[i], parkedHl[i], parkedHw[i]), tick);
            }
        }
        keep(NearMiss.ROAD_EDGE, roadEdges.margin(cx, cy, fx, fy, hl, hw), tick);
        watchCentreLine(car, cx, cy, fx, fy, hl, hw, tick);
        watchMoving(run, car, cx, cy, fx, fy, hl, hw, reach, tick);
        watchSquares(run, cx, cy, fx, fy, hl, hw, reach, tick);

        if (run.failure() != null) {
            timeoutRho = Double.NaN;
        } else if (run.reachedTarget()) {
            timeoutRho = Dynamics.TIMEOUT_TICKS - tick;
        } else if (tick + 1 >= Dynamics.TIMEOUT_TICKS) {
            timeoutRho = 0;
        }
    }

    private void watchCentreLine(Vehicle car, double cx, double cy, double fx, double fy, double hl, double hw, long tick) {
        double margin = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 4; k++) {
            // the corners as Box.corners() makes them
            double along = k < 2 ? hl : -hl;
            double across = k == 0 || k == 3 ? hw : -hw;
            double x = cx + along * fx + across * fy;
            double y = cy + along * fy - across * fx;
            if (inJunction(x, y)) {
                continue;
            }
            for (int index : network.roadsNear(x, y)) {
                Road road = roads[index];
                if (road.contains(x, y)) {
                    // NORTH and EAST lanes are the first half, across < centre
                    boolean firstHalf = switch (CentreLine.laneOn(road, car.headingDx(), car.headingDy())) {
                        case NORTH, EAST -> true;
                        case SOUTH, WEST -> false;
                    };
                    double off = road.across(x, y) - road.centre();
                    margin = Math.min(margin, firstHalf ? -off : off);
                }
            }
        }
        if (margin < -EPS && centreLineExcuse.applies(car.footprint())) {
            return;
        }
        keep(NearMiss.CENTRE_LINE, margin, tick);
    }

    private boolean inJunction(double x, double y) {
        for (Junction j : junctions) {
            if (j.contains(x, y)) {
                return true;
            }
        }
        return false;
    }

    private void watchMoving(Telemetry run, Vehicle car, double cx, double cy, double fx, double fy, double hl, double hw,
                             double reach, long tick) {
        List<? extends Vehicle> moving = run.movingCars();
        double vx = car.speed() * fx;
        double vy = car.speed() * fy;
        for (int i = 0; i < moving.size(); i++) {
            Vehicle other = moving.get(i);
            if (!other.isActive()) {
                touching[i] = false;
                continue;
            }
            double ofx = other.headingDx();
            double ofy = other.headingDy();
            double ohl = other.length() / 2;
            double ohw = other.width() / 2;
            double ocx = other.x() - ohl * ofx;
            double ocy = other.y() - ohl * ofy;
            keep(NearMiss.TIME_TO_COLLISION, BoxGap.timeToContact(cx, cy, fx, fy, hl, hw, vx, vy,
                    ocx, ocy, ofx, ofy, ohl, ohw, other.speed() * ofx, other.speed() * ofy), tick);
            double bound = Math.sqrt((ocx - cx) * (ocx - cx) + (ocy - cy) * (ocy - cy)) - reach - Math.sqrt(ohl * ohl + ohw * ohw);
            if (bound > 0 && bound >= otherCarRho && bound >= least[NearMiss.MOVING_GAP.ordinal()]) {
                touching[i] = false;
                continue;
            }
            double gap = BoxGap.signedDistance(cx, cy, fx, fy, hl, hw, ocx, ocy, ofx, ofy, ohl, ohw);
            keep(NearMiss.MOVING_GAP, gap, tick);
            boolean now = gap < -EPS;
            if (now && !touching[i]) {
                // the detector's judgement of the contact, made as it makes it
                boolean over = centreLine.isOver(car.footprint(), car.headingDx(), car.headingDy());
                excused[i] = !BlameRules.judge(car, other, centreLine, over).isAccident();
            }
            touching[i] = now;
            if (!(now && excused[i]) && gap < otherCarRho) {
                otherCarRho = gap;
            }
        }
    }

    private void watchSquares(Telemetry run, double cx, double cy, double fx, double fy, double hl, double hw,
                              double reach, long tick) {
        int squares = squareX.length;
        boolean anyCarEnters = false;
        for (int j = 0; j < squares; j++) {
            boolean carNow = inSquare(j, cx, cy, fx, fy, hl, hw, reach);
            carEnters[j] = carNow && !carIn[j];
            anyCarEnters |= carEnters[j];
            if (!carNow && carIn[j]) {
                carLeft[j] = tick;
            }
            carIn[j] = carNow;
        }
        // each vehicle's footprint is worked out once, not once per square: the same values, so the same answers
        List<? extends Vehicle> moving = run.movingCars();
        for (int i = 0; i < moving.size(); i++) {
            Vehicle other = moving.get(i);
            boolean active = other.isActive();
            double ofx = 0;
            double ofy = 0;
            double ohl = 0;
            double ohw = 0;
            double ocx = 0;
            double ocy = 0;
            double oreach = 0;
            if (active) {
                ohl = other.length() / 2;
                ohw = other.width() / 2;
                ofx = other.headingDx();
                ofy = other.headingDy();
                ocx = other.x() - ohl * ofx;
                ocy = other.y() - ohl * ofy;
                oreach = Math.sqrt(ohl * ohl + ohw * ohw);
            }
            if (!anyCarEnters && inCount[i] == 0 && (!active || HALF_SQUARE + oreach < SquareGrid.REACH)) {
                // the usual tick: the car entered no square and this vehicle is in none, so only a square it
                // enters now changes anything, and only the squares near it can be entered
                if (active) {
                    enterNear(i, ocx, ocy, ofx, ofy, ohl, ohw, oreach, tick);
                }
                continue;
            }
            for (int j = 0; j < squares; j++) {
                int at = i * squares + j;
                boolean otherNow = active && inSquare(j, ocx, ocy, ofx, ofy, ohl, ohw, oreach);
                boolean otherEnters = otherNow && !otherIn[at];
                if (!otherNow && otherIn[at]) {
                    otherLeft[at] = tick;
                    inCount[i]--;
                }
                if (otherEnters) {
                    inCount[i]++;
                }
                otherIn[at] = otherNow;
                // the order of these within a tick does not matter: keep takes the least, and the tick is the same
                if (carEnters[j] && !otherNow && otherLeft[at] >= 0) {
                    keep(NearMiss.POST_ENCROACHMENT, tick - otherLeft[at], tick);
                }
                if (otherEnters && !carIn[j] && carLeft[j] >= 0) {
                    keep(NearMiss.POST_ENCROACHMENT, tick - carLeft[j], tick);
                }
            }
        }
    }

    /**
     * What the loop over every square does for moving vehicle {@code i} when the car entered no square
     * and the vehicle was in none: note each square it is in now as entered, beside the car or after it.
     */
    private void enterNear(int i, double ocx, double ocy, double ofx, double ofy, double ohl, double ohw, double oreach,
                           long tick) {
        int squares = squareX.length;
        for (int j : squareGrid.near(ocx, ocy)) {
            if (inSquare(j, ocx, ocy, ofx, ofy, ohl, ohw, oreach)) {
                otherIn[i * squares + j] = true;
                inCount[i]++;
                if (!carIn[j] && carLeft[j] >= 0) {
                    keep(NearMiss.POST_ENCROACHMENT, tick - carLeft[j], tick);
                }
            }
        }
    }

    /** Whether a footprint's interior overlaps square j (beyond the detector's tolerance). */
    private boolean inSquare(int j, double cx, double cy, double fx, double fy, double hl, double hw, double reach) {
        double dx = Math.abs(cx - squareX[j]);
        double dy = Math.abs(cy - squareY[j]);
        if (dx >= HALF_SQUARE + reach || dy >= HALF_SQUARE + reach) {
            return false;
        }
        return BoxGap.penetration(cx, cy, fx, fy, hl, hw, squareX[j], squareY[j], 0, 1, HALF_SQUARE, HALF_SQUARE) > EPS;
    }

    private void keep(NearMiss measure, double value, long tick) {
        int m = measure.ordinal();
        if (value < least[m]) {
            least[m] = value;
            leastTick[m] = tick;
        }
    }

    /** The least value of the measure so far: infinite when never met. */
    public double least(NearMiss measure) {
        return least[measure.ordinal()];
    }

    /** The tick the least value was first reached, or −1. */
    public long tickOf(NearMiss measure) {
        return leastTick[measure.ordinal()];
    }

    /** The robustness ρ of the requirement that no accident of {@code type} happens (see the class comment). */
    public double robustness(AccidentType type) {
        return switch (type) {
            case CLASHWITHOBSTACLE -> least(NearMiss.PARKED_GAP);
            case CLASHWITHOTHERCAR -> otherCarRho;
            case LEAVEROAD -> least(NearMiss.ROAD_EDGE);
            case CROSSCENTRELINE -> least(NearMiss.CENTRE_LINE);
            case TIMEOUT -> timeoutRho;
        };
    }

    /** Every measure's least value, in {@link NearMiss} order (a copy, for reports). */
    public Map<NearMiss, Double> measures() {
        Map<NearMiss, Double> all = new EnumMap<>(NearMiss.class);
        for (NearMiss m : NearMiss.values()) {
            all.put(m, least(m));
        }
        return all;
    }
}
