package sitcov.builtin;

import java.util.List;
import java.util.Set;
import java.util.random.RandomGenerator;
import sitcov.control.Command;
import sitcov.control.Controller;
import sitcov.control.ControllerFactory;
import sitcov.control.ControllerSource;
import sitcov.control.Observation;
import sitcov.control.RunStart;
import sitcov.control.Vehicle;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.faults.PlantedFaults;
import sitcov.faults.SeededControllerFactory;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.sensors.CameraSettings;
import sitcov.sensors.LaneEstimate;
import sitcov.sensors.Lidar;
import sitcov.sensors.MarkingCamera;
import sitcov.sensors.TrafficSensor;
import sitcov.vehicles.AutonomousCar;
import sitcov.vehicles.Bodied;
import sitcov.vehicles.Body;
import sitcov.vehicles.Dynamics;
import sitcov.vehicles.Lanes;
import sitcov.world.Dimensions;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;
import sitcov.world.StartPose;
import sitcov.world.Target;
import sitcov.world.WorldMap;

/**
 * The builtin controller: sitcov's own autonomous car, the first system under test, its twenty
 * seeded faults its variants. Each tick it takes what the observation gives it — its pose, the road
 * map and Target, the traffic and obstacles its radar and LIDAR report, the junctions' right-of-way
 * — looks for road markings (camera) and parked cars (LIDAR) among them, lets its behaviours state
 * what they want (junctions, overtaking, keeping its distance, reaching the Target, keeping its
 * lane) and commands one speed change and one turn of at most 15°. Seeded faults act at the seams
 * each behaviour names. It keeps a model of its own body to plan with, set each tick to the pose
 * the world reports; the world alone moves the car.
 */
public final class BuiltinCar implements Controller, Bodied {
    /** The stream its own random decisions (the choice among exits already taken) come from. */
    public static final String DECISIONS_STREAM = "autonomous-car.decisions";
    static final double LOOKAHEAD = 6;
    static final double REAR_AXLE = AutonomousCar.REAR_AXLE;
    /** A lane centre seen further than this to the side, outside an overtake, is not believed. */
    static final double IMPLAUSIBLE_OFFSET = 1.3;

    private RoadNetwork roads;
    private Target target;
    private FaultSwitchboard faults;
    private Body body;
    private Observation now;
    private JunctionRequests rightOfWay = new JunctionRequests();
    private MarkingCamera camera;
    /** A camera for each camera fault a fault-free run watches from the shadows, made when first needed. */
    private MarkingCamera[] shadowCameras = new MarkingCamera[CameraFaults.CAMERA.size()];
    private Lidar lidar;
    private TrafficSensor traffic = new TrafficSensor();
    private Waypoints waypoints;
    private JunctionDriver junctions;
    private Overtaker overtaker;
    private TargetSeeker targetSeeker;
    private Intent intent = new Intent();
    private Compass lane;
    private LaneEstimate estimate = LaneEstimate.NOTHING_SEEN;
    private LaneMemory laneMemory = new LaneMemory();
    private double laneCentre;

    /**
     * The builtin car for one run on {@code map}, starting at its start pose, with the faults of
     * {@code faults} switched on; its random choices come from {@code decisions}.
     */
    public BuiltinCar(WorldMap map, FaultSwitchboard faults, RandomGenerator decisions) {
        StartPose start = map.layout().carStart()
                .orElseThrow(() -> new IllegalArgumentException("map " + map.seed() + " has no start for the car"));
        this.roads = RoadNetwork.of(map.layout());
        this.target = map.layout().target()
                .orElseThrow(() -> new IllegalArgumentException("map " + map.seed() + " has no Target"));
        this.faults = faults;
        this.body = new Body(start.position().x(), start.position().y(), start.heading().bearing(), REAR_AXLE);
        this.lane = start.heading();
        this.camera = new MarkingCamera(roads);
        this.lidar = new Lidar(roads);
        this.waypoints = new Waypoints(faults);
        this.junctions = new JunctionDriver(this, faults, decisions, Route.plan(roads, target), roads.junctions().size());
        this.overtaker = new Overtaker(this, faults);
        this.targetSeeker = new TargetSeeker(this, faults);
    }

    /** The builtin car of each run, with the run's faults switched on. */
    public static final SeededControllerFactory FACTORY = new SeededControllerFactory() {
        @Override
        public Controller start(RunStart run, FaultSwitchboard faults) {
            return new BuiltinCar(run.map(), faults, run.streams().stream(DECISIONS_STREAM));
        }

        /** All its state is in its own objects, which a checkpoint of the run copies. */
        @Override
        public boolean copyable() {
            return true;
        }
    };

    /**
     * The builtin car with {@code planted} always on, whatever the run switches on: a version of it
     * with bugs, for comparing versions. What every fault does is recorded on the run's board.
     */
    public static PlantedFaults withPlanted(Set<Fault> planted) {
        return FACTORY.withPlanted(planted);
    }

    /** The builtin car for every worker thread (it holds no process or other resource). */
    public static final ControllerSource SOURCE = new ControllerSource() {
        @Override
        public ControllerFactory forThisThread() {
            return FACTORY;
        }

        @Override
        public String spec() {
            return "builtin";
        }
    };

    @Override
    public void step(Observation observation, Command out) {
        now = observation;
        body.sync(observation.x(), observation.y(), observation.heading(), observation.speed());
        rightOfWay.startTick(observation.rightOfWay(), out);
        intent.reset();
        followHeadingIntoLane();
        estimate = lookForMarkings();
        laneCentre = laneMemory.laneCentre(lane, body.x(), body.y(), estimate);
        traffic.scan(observation.traffic(), this, lane, laneCentre, -5, 40);
        junctions.releaseIfLeft();
        junctions.plan(intent, lane);
        if (!junctions.isCrossing()) {
            overtaker.plan(intent, lane, laneCentre);
        }
        keepDistance();
        targetSeeker.plan(intent, lane, estimate);
        keepLane();
        drive(out);
        out.report().overtaking(overtaker.stage().isPassing()).crossingJunction(junctions.isCrossing())
                .waitingAtJunction(junctions.isWaiting()).lane(lane).stage(overtaker.stage().name())
                .limitedBy(intent.limitedBy()).steeredBy(intent.steeredBy());
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
        CameraSettings settings = CameraFaults.settings(faults);
        LaneEstimate seen = camera.look(body.x(), body.y(), lane, settings);
        camera.keepHits();
        if (settings != CameraSettings.STANDARD && !CameraFaults.allRecorded(faults)) {
            // the standard look only tells whether the degraded one saw otherwise: the car drives on the degraded one
            LaneEstimate correct = camera.look(body.x(), body.y(), lane, CameraSettings.STANDARD);
            CameraFaults.record(faults, !seen.equals(correct));
        } else {
            CameraFaults.watchFromShadows(faults, shadowCameras, camera, body.x(), body.y(), lane, seen);
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

    /** Works the speed and turn out on its model body and commands them; the world then moves the car. */
    private void drive(Command out) {
        double limit = intent.speedLimit();
        if (intent.isCrawl() && limit >= Dynamics.CRAWL_CEILING) {
            crawl();
        } else {
            body.approachSpeed(limit);
        }
        out.speed(body.speed());
        out.steering(Body.turnTowards(body.heading(), intent.bearing(), Dynamics.MAX_TURN));
    }

    /** Holds speed in the crawl band (faults 5 and 6 act here). */
    private void crawl() {
        if (body.speed() < Dynamics.CRAWL_FLOOR) {
            body.accelerate();
            if (faults.watches(Fault.CRAWL_DOUBLE_ACCELERATION)) {
                if (faults.isActive(Fault.CRAWL_DOUBLE_ACCELERATION)) {
                    body.accelerate();
                }
                faults.effective(Fault.CRAWL_DOUBLE_ACCELERATION);
            }
        } else if (body.speed() >= Dynamics.CRAWL_CEILING) {
            body.brake();
            if (faults.watches(Fault.CRAWL_DOUBLE_BRAKING)) {
                if (faults.isActive(Fault.CRAWL_DOUBLE_BRAKING)) {
                    body.brake();
                }
                faults.effective(Fault.CRAWL_DOUBLE_BRAKING);
            }
        }
    }

    Road road(Compass direction) {
        return Lanes.roadAlong(roads, body.x(), body.y(), direction);
    }

    void setLane(Compass direction) {
        lane = direction;
    }

    RoadNetwork roads() {
        return roads;
    }

    Target target() {
        return target;
    }

    long tick() {
        return now.tick();
    }

    /** Parked cars its LIDAR reports this tick. */
    List<Box> obstacles() {
        return now.obstacles();
    }

    /** Vehicles its radar reports this tick. */
    List<Vehicle> trafficTracks() {
        return now.traffic();
    }

    JunctionRequests rightOfWay() {
        return rightOfWay;
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
        return AutonomousCar.ID;
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
