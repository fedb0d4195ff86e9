package sitcov.vehicles;

import java.util.ArrayList;
import java.util.List;
import java.util.random.RandomGenerator;
import sitcov.control.Controller;
import sitcov.control.ControllerFactory;
import sitcov.control.RunStart;
import sitcov.control.Vehicle;
import sitcov.engine.SimState;
import sitcov.geom.Box;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.ParkedCar;
import sitcov.world.RoadNetwork;
import sitcov.world.StartPose;
import sitcov.world.Target;
import sitcov.world.WorldMap;

/**
 * Everything the vehicles of one run share: the road network, the parked cars, the Target, the
 * junction locks, and the vehicles themselves. Sensors read it; only the vehicles change it.
 */
public final class Scene {
    /** Vehicles step at ordering 0; whoever watches them (the accident detector) steps after, at 1. */
    public static final int VEHICLE_ORDERING = 0;

    private WorldMap map;
    private RoadNetwork network;
    private List<ParkedCar> parkedCars;
    private List<Box> parkedBodies;
    private JunctionOccupancy occupancy;
    private SimState state;
    // unmodifiable, set once the scene is built: callers ask for them many times a tick
    private List<MovingCar> movingCars = List.of();
    private List<Vehicle> vehicles = List.of();
    /** The same vehicles in a plain array, for the passes every car makes over the traffic each tick. */
    private Vehicle[] vehicleArray = new Vehicle[0];
    private AutonomousCar autonomousCar;
    private Telemetry telemetry = new SceneTelemetry(this);

    Scene(WorldMap map, SimState state) {
        this.map = map;
        Layout layout = map.layout();
        this.network = RoadNetwork.of(layout);
        this.parkedCars = layout.parkedCars();
        this.parkedBodies = parkedCars.stream().map(ParkedCar::footprint).toList();
        this.occupancy = new JunctionOccupancy(layout.junctions().size());
        this.state = state;
    }

    /**
     * Builds the scene of {@code map} for one run: the car under test at its start, driven by the
     * controller {@code controllers} makes for this run, and a moving car at each moving-car start,
     * all scheduled every tick from tick 0, in an order shuffled every tick.
     */
    public static Scene start(WorldMap map, SimState state, ControllerFactory controllers) {
        Scene scene = new Scene(map, state);
        StartPose start = map.layout().carStart()
                .orElseThrow(() -> new IllegalArgumentException("map " + map.seed() + " has no start for the car"));
        map.layout().target().orElseThrow(() -> new IllegalArgumentException("map " + map.seed() + " has no Target"));
        Controller controller = controllers.start(new RunStart(map, state.seed(), state.streams(), state::tick));
        AutonomousCar car = new AutonomousCar(scene, start, controller);
        scene.autonomousCar = car;
        state.schedule().scheduleRepeating(0, VEHICLE_ORDERING, 1, car);
        List<MovingCar> moving = new ArrayList<>();
        RandomGenerator choices = state.random(MovingCar.CHOICES_STREAM);
        RandomGenerator respawns = state.random(MovingCar.RESPAWNS_STREAM);
        int id = AutonomousCar.ID + 1;
        for (StartPose pose : map.movingCars()) {
            MovingCar next = new MovingCar(id++, scene, pose, choices, respawns);
            moving.add(next);
            state.schedule().scheduleRepeating(0, VEHICLE_ORDERING, 1, next);
        }
        List<Vehicle> all = new ArrayList<>();
        all.add(car);
        all.addAll(moving);
        scene.movingCars = List.copyOf(moving);
        scene.vehicles = List.copyOf(all);
        scene.vehicleArray = all.toArray(new Vehicle[0]);
        return scene;
    }

    public WorldMap map() {
        return map;
    }

    public RoadNetwork network() {
        return network;
    }

    public List<ParkedCar> parkedCars() {
        return parkedCars;
    }

    /** Parked-car footprints, in parked-car order. */
    public List<Box> parkedBodies() {
        return parkedBodies;
    }

    public Target target() {
        return map.layout().target().orElseThrow(() -> new IllegalStateException("the map has no Target"));
    }

    public JunctionOccupancy occupancy() {
        return occupancy;
    }

    public long tick() {
        return state.tick();
    }

    public SimState state() {
        return state;
    }

    /** The run's telemetry: what watchers of the run receive. */
    public Telemetry telemetry() {
        return telemetry;
    }

    public AutonomousCar autonomousCar() {
        return autonomousCar;
    }

    public List<MovingCar> movingCars() {
        return movingCars;
    }

    /** Every vehicle, the autonomous car first; check {@link Vehicle#isActive()} before using one. */
    public List<Vehicle> vehicles() {
        return vehicles;
    }

    /** {@link #vehicles()} as an array, the autonomous car first: read it, never write it. */
    Vehicle[] vehicleArray() {
        return vehicleArray;
    }

    /** Whether any active vehicle other than {@code self} has part of its footprint in the junction's square. */
    boolean isOccupiedByOther(Junction junction, Vehicle self) {
        double jx = junction.centre().x();
        double jy = junction.centre().y();
        for (Vehicle v : vehicleArray) {
            // a vehicle whose front is further than its length plus the square's half-diagonal cannot reach in
            double reach = v.length() + 4.3;
            if (v != self && v.isActive() && Math.abs(v.x() - jx) < reach && Math.abs(v.y() - jy) < reach
                    && v.footprint().overlaps(junction.square())) {
                return true;
            }
        }
        return false;
    }

    /** Adds a moving car to a scene built by hand, without a run (sensor tests). */
    void addMovingCar(MovingCar car) {
        List<MovingCar> moving = new ArrayList<>(movingCars);
        moving.add(car);
        List<Vehicle> all = new ArrayList<>(vehicles);
        all.add(car);
        movingCars = List.copyOf(moving);
        vehicles = List.copyOf(all);
        vehicleArray = all.toArray(new Vehicle[0]);
    }
}
