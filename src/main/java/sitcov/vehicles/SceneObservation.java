package sitcov.vehicles;

import java.util.ArrayList;
import java.util.List;
import sitcov.control.Channel;
import sitcov.control.Observation;
import sitcov.control.RightOfWay;
import sitcov.control.Vehicle;
import sitcov.engine.ReadOnlyView;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.sensors.CameraSettings;
import sitcov.sensors.Lidar;
import sitcov.sensors.MarkingCamera;
import sitcov.world.Junction;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;
import sitcov.world.Target;

/**
 * The world's side of the observation: refreshed once a tick for the car under test, filled from
 * the scene without allocating (its lists are reused). The standard camera's and LIDAR's raw hits
 * are worked out only when a controller first asks for them in a tick.
 */
final class SceneObservation implements Observation, RightOfWay {
    private Scene scene;
    private AutonomousCar car;
    private List<Vehicle> traffic = new ArrayList<>();
    private List<Box> obstacles = new ArrayList<>();
    private List<Vehicle> trafficView = new ReadOnlyView<>(traffic);
    private List<Box> obstaclesView = new ReadOnlyView<>(obstacles);
    private MarkingCamera camera;
    private Lidar lidar;
    private long cameraTick = -1;
    private long lidarTick = -1;
    private long tick;

    SceneObservation(Scene scene, AutonomousCar car) {
        this.scene = scene;
        this.car = car;
    }

    void refresh(long now) {
        tick = now;
        // what was worked out before this refresh (a viewer looks between ticks) saw other traffic
        cameraTick = -1;
        lidarTick = -1;
        double x = car.x();
        double y = car.y();
        double rangeSq = SENSOR_RANGE * SENSOR_RANGE;
        traffic.clear();
        List<Vehicle> vehicles = scene.vehicles();
        for (int i = 0, n = vehicles.size(); i < n; i++) {
            Vehicle v = vehicles.get(i);
            double dx = v.x() - x;
            double dy = v.y() - y;
            if (v != car && v.isActive() && dx * dx + dy * dy <= rangeSq) {
                traffic.add(v);
            }
        }
        obstacles.clear();
        List<Box> parked = scene.parkedBodies();
        for (int i = 0, n = parked.size(); i < n; i++) {
            Box b = parked.get(i);
            double dx = b.centreX() - x;
            double dy = b.centreY() - y;
            if (dx * dx + dy * dy <= rangeSq) {
                obstacles.add(b);
            }
        }
    }

    @Override
    public long tick() {
        return tick;
    }

    @Override
    public double x() {
        return car.x();
    }

    @Override
    public double y() {
        return car.y();
    }

    @Override
    public double heading() {
        return car.heading();
    }

    @Override
    public double speed() {
        return car.speed();
    }

    @Override
    public RoadNetwork roads() {
        return scene.network();
    }

    @Override
    public Target target() {
        return scene.target();
    }

    @Override
    public List<Vehicle> traffic() {
        return trafficView;
    }

    @Override
    public List<Box> obstacles() {
        return obstaclesView;
    }

    @Override
    public RightOfWay rightOfWay() {
        return this;
    }

    @Override
    public boolean holds(int junction) {
        return inRange(junction) && scene.occupancy().isHeldBy(junction, AutonomousCar.ID);
    }

    @Override
    public boolean wouldGrant(int junction) {
        if (!inRange(junction)) {
            return false;
        }
        JunctionOccupancy occupancy = scene.occupancy();
        int holder = occupancy.holder(junction);
        return !scene.isOccupiedByOther(scene.network().junctions().get(junction), car)
                && (holder == AutonomousCar.ID || holder < 0 || tick - occupancy.since(junction) > AutonomousCar.PATIENCE);
    }

    private boolean inRange(int junction) {
        return junction >= 0 && junction < scene.network().junctions().size();
    }

    @Override
    public int cameraHits() {
        return look().keptHits();
    }

    @Override
    public double cameraHitX(int hit) {
        return look().keptX(hit);
    }

    @Override
    public double cameraHitY(int hit) {
        return look().keptY(hit);
    }

    private MarkingCamera look() {
        if (camera == null) {
            camera = new MarkingCamera(scene.network());
        }
        if (cameraTick != tick) {
            camera.look(car.x(), car.y(), Compass.nearest(car.heading()), CameraSettings.STANDARD);
            camera.keepHits();
            cameraTick = tick;
        }
        return camera;
    }

    @Override
    public int lidarHits() {
        return sweep().hits();
    }

    @Override
    public double lidarHitX(int hit) {
        return sweep().worldX(hit);
    }

    @Override
    public double lidarHitY(int hit) {
        return sweep().worldY(hit);
    }

    private Lidar sweep() {
        if (lidar == null) {
            lidar = new Lidar(scene.network());
        }
        if (lidarTick != tick) {
            lidar.sweep(car.x(), car.y(), car.heading(), Compass.nearest(car.heading()), obstacles, traffic, car);
            lidarTick = tick;
        }
        return lidar;
    }

    @Override
    public double channel(Channel channel) {
        Compass lane = Compass.nearest(car.heading());
        return switch (channel) {
            case LANE_OFFSET -> laneOffset(lane);
            case HEADING_ERROR -> Bearing.turn(lane.bearing(), car.heading());
            case DISTANCE_TO_JUNCTION -> distanceToJunction(lane);
            case TARGET_DISTANCE -> scene.target().position().distanceTo(car.x(), car.y());
        };
    }

    private double laneOffset(Compass lane) {
        Road road = Lanes.roadAlong(scene.network(), car.x(), car.y(), lane);
        if (road == null) {
            return Double.NaN;
        }
        double centre = road.laneCentre(lane);
        double across = road.across(car.x(), car.y());
        // metres to the right of the lane's direction: right of north is east (larger x), and so on
        double rightward = road.isNorthSouth() ? lane.right().dx() : lane.right().dy();
        return (across - centre) * Math.signum(rightward);
    }

    private double distanceToJunction(Compass lane) {
        Road road = Lanes.roadAlong(scene.network(), car.x(), car.y(), lane);
        if (road == null) {
            return Double.NaN;
        }
        Junction next = Lanes.nextJunction(scene.network(), road, lane, car.x(), car.y());
        return next == null ? Double.NaN : Lanes.distanceToSquare(next, lane, car.x(), car.y());
    }
}
