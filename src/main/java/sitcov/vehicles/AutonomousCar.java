package sitcov.vehicles;

import java.util.random.RandomGenerator;
import sitcov.engine.SimState;
import sitcov.engine.Steppable;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.world.Dimensions;
import sitcov.world.Road;
import sitcov.world.StartPose;

/**
 * The autonomous car, the system under test. Each tick it looks (road-marking camera, LIDAR,
 * traffic radar), then lets its behaviours state what they want — junctions, overtaking, keeping
 * its distance, reaching the Target, keeping its lane — and drives: one speed change, one turn of
 * at most 15°, one move. Seeded faults act at the seams each behaviour names.
 */
public final class AutonomousCar implements Vehicle, Steppable {
    public static final int ID = 0;
    /** The stream its own random decisions (the choice among exits already taken) come from. */
    public static final String DECISIONS_STREAM = "autonomous-car.decisions";
    static final double LOOKAHEAD = 6;
    /** Its rear axle, which it turns about, is this far behind its front. */
    static final double REAR_AXLE = 1.5;
    /** A lane centre seen further than this to the side, outside an overtake, is not believed. */
    static final double IMPLAUSIBLE_OFFSET = 1.3;

    private final Scene scene;
    private final FaultSwitchboard faults;
    private final Body body;
    private Box keptClear;
    private Box keptClearOf;
    private final CameraSettings cameraSettings;
    private final MarkingCamera camera;
    private final Lidar lidar;
    private final TrafficSensor traffic = new TrafficSensor();
    private final Waypoints waypoints;
    private final JunctionDriver junctions;
    private final Overtaker overtaker;
    private final TargetSeeker targetSeeker;
    private final Intent intent = new Intent();
    private Compass lane;
    private LaneEstimate estimate = LaneEstimate.NOTHING_SEEN;
    private final LaneMemory laneMemory = new LaneMemory();
    private double laneCentre;
    private boolean reachedTarget;

    AutonomousCar(Scene scene, StartPose start, FaultSwitchboard faults, RandomGenerator decisions) {
        this.scene = scene;
        this.faults = faults;
        this.body = new Body(start.position().x(), start.position().y(), start.heading().bearing(), REAR_AXLE);
        this.lane = start.heading();
        this.cameraSettings = CameraFaults.settings(faults);
        this.camera = new MarkingCamera(scene.network());
        this.lidar = new Lidar(scene.network());
        this.waypoints = new Waypoints(faults);
        this.junctions = new JunctionDriver(this, faults, decisions,
                Route.plan(scene.network(), scene.target()), scene.network().junctions().size());
        this.overtaker = new Overtaker(this, faults);
        this.targetSeeker = new TargetSeeker(this, faults);
    }

    @Override
    public void step(SimState state) {
        if (reachedTarget) {
            return;
        }
        intent.reset();
        followHeadingIntoLane();
        estimate = lookForMarkings();
        laneCentre = laneMemory.laneCentre(lane, body.x(), body.y(), estimate);
        traffic.scan(scene, this, lane, laneCentre, -5, 40);
        junctions.releaseIfLeft();
        junctions.plan(intent, lane);
        if (!junctions.isCrossing()) {
            overtaker.plan(intent, lane, laneCentre);
        }
        keepDistance();
        targetSeeker.plan(intent, lane, estimate);
        keepLane();
        drive();
        reachedTarget = targetSeeker.isReached(lane, estimate);
    }

    /** Outside junctions and manoeuvres the lane direction follows the car's heading. */
    private void followHeadingIntoLane() {
        if (junctions.isCrossing() || overtaker.stage().isPassing()) {
            return;
        }
        Compass nearest = Compass.nearest(body.heading());
        if (Math.abs(Bearing.turn(body.heading(), nearest.bearing())) < 30) {
            lane = nearest;
        }
    }

    private LaneEstimate lookForMarkings() {
        LaneEstimate seen = camera.look(body.x(), body.y(), lane, cameraSettings);
        camera.keepHits();
        if (cameraSettings != CameraSettings.STANDARD) {
            LaneEstimate correct = camera.look(body.x(), body.y(), lane, CameraSettings.STANDARD);
            CameraFaults.record(faults, !seen.equals(correct));
        }
        // Driving its lane, the car is never far off its lane centre: a sighting that says so is
        // another road's lines, seen across a junction, and is not believed.
        if (!overtaker.stage().isPassing() && Math.abs(seen.laneCentre()) > IMPLAUSIBLE_OFFSET) {
            return LaneEstimate.NOTHING_SEEN;
        }
        return seen;
    }

    /** Keeps a stopping distance to whatever moves in its path. */
    private void keepDistance() {
        double gap = traffic.pathGap();
        if (Double.isInfinite(gap)) {
            return;
        }
        double lead = traffic.pathSpeed();
        double room = lead >= 0
                ? gap + Dynamics.stoppingDistance(lead) - lead - 2
                : gap - 2 + 4 * lead;
        intent.stopWithin(room, "traffic");
    }

    /** Steers to the lane centre the camera sees, a lookahead ahead; straight on when it sees none. */
    private void keepLane() {
        double offset = estimate.anySeen() ? estimate.laneCentre() : 0;
        intent.steer(lane.bearing() - Math.toDegrees(Math.atan2(offset, LOOKAHEAD)), "lane");
    }

    private void drive() {
        double limit = intent.speedLimit();
        if (intent.isCrawl() && limit >= Dynamics.CRAWL_CEILING) {
            crawl();
        } else {
            body.approachSpeed(limit);
        }
        body.turnTowards(intent.bearing(), Dynamics.MAX_TURN);
        body.move();
    }

    /** Holds speed in the crawl band (faults 5 and 6 act here). */
    private void crawl() {
        if (body.speed() < Dynamics.CRAWL_FLOOR) {
            body.accelerate();
            if (faults.isActive(Fault.CRAWL_DOUBLE_ACCELERATION)) {
                body.accelerate();
                faults.effective(Fault.CRAWL_DOUBLE_ACCELERATION);
            }
        } else if (body.speed() >= Dynamics.CRAWL_CEILING) {
            body.brake();
            if (faults.isActive(Fault.CRAWL_DOUBLE_BRAKING)) {
                body.brake();
                faults.effective(Fault.CRAWL_DOUBLE_BRAKING);
            }
        }
    }

    Road road(Compass direction) {
        return Lanes.roadAlong(scene.network(), body.x(), body.y(), direction);
    }

    void setLane(Compass direction) {
        lane = direction;
    }

    Scene scene() {
        return scene;
    }

    Waypoints waypoints() {
        return waypoints;
    }

    Lidar lidar() {
        return lidar;
    }

    TrafficSensor traffic() {
        return traffic;
    }

    /** Whether it stands on the Target (the run is then over). */
    public boolean hasReachedTarget() {
        return reachedTarget;
    }

    public OvertakingStage overtakingStage() {
        return overtaker.stage();
    }

    /** Whether it is turning through a junction square (being over the centre line is then justified). */
    public boolean isCrossingJunction() {
        return junctions.isCrossing();
    }

    /** How many of the camera's rays met a marking in this tick's look (a viewer draws them). */
    public int cameraHits() {
        return camera.keptHits();
    }

    public double cameraHitX(int hit) {
        return camera.keptX(hit);
    }

    public double cameraHitY(int hit) {
        return camera.keptY(hit);
    }

    /** How many rays of the LIDAR's last sweep hit something; where it stood and where they hit. */
    public int lidarHits() {
        return lidar.hits();
    }

    public double lidarOriginX() {
        return lidar.originX();
    }

    public double lidarOriginY() {
        return lidar.originY();
    }

    public double lidarHitX(int hit) {
        return lidar.worldX(hit);
    }

    public double lidarHitY(int hit) {
        return lidar.worldY(hit);
    }

    public boolean isWaitingAtJunction() {
        return junctions.isWaiting();
    }

    /** The lane direction it is driving. */
    public Compass lane() {
        return lane;
    }

    /** Where it believes its lane centre is, metres to its right. */
    public double believedLaneCentre() {
        return laneCentre;
    }

    /** Which behaviour set the speed limit in the last tick (null when none did). */
    public String limitedBy() {
        return intent.limitedBy();
    }



    /** Which behaviour steered in the last tick. */
    public String steeredBy() {
        return intent.steeredBy();
    }

    @Override
    public int id() {
        return ID;
    }

    @Override
    public double x() {
        return body.x();
    }

    @Override
    public double y() {
        return body.y();
    }

    @Override
    public double heading() {
        return body.heading();
    }

    @Override
    public double headingDx() {
        return body.headingDx();
    }

    @Override
    public double headingDy() {
        return body.headingDy();
    }

    @Override
    public double speed() {
        return body.speed();
    }

    @Override
    public double length() {
        return Dimensions.AUTONOMOUS_CAR_LENGTH;
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
    public Box footprint() {
        return body.footprint(length(), width());
    }

    @Override
    public double width() {
        return Dimensions.AUTONOMOUS_CAR_WIDTH;
    }

    @Override
    public boolean isActive() {
        return true;
    }
}
