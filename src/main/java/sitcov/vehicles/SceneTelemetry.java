package sitcov.vehicles;

import java.util.List;
import sitcov.control.ControllerFailure;
import sitcov.control.Observation;
import sitcov.control.SelfReport;
import sitcov.control.Vehicle;
import sitcov.geom.Box;
import sitcov.world.RoadNetwork;
import sitcov.world.WorldMap;

/** The world's telemetry of one run: read-only answers from the scene as it stands after the tick. */
final class SceneTelemetry implements Telemetry {
    private Scene scene;

    SceneTelemetry(Scene scene) {
        this.scene = scene;
    }

    @Override
    public long tick() {
        return scene.tick();
    }

    @Override
    public WorldMap map() {
        return scene.map();
    }

    @Override
    public RoadNetwork network() {
        return scene.network();
    }

    @Override
    public List<Box> parkedBodies() {
        return scene.parkedBodies();
    }

    @Override
    public Vehicle car() {
        return scene.autonomousCar();
    }

    @Override
    public double speedChange() {
        return scene.autonomousCar().appliedSpeedChange();
    }

    @Override
    public double steering() {
        return scene.autonomousCar().appliedSteering();
    }

    @Override
    public boolean clamped() {
        return scene.autonomousCar().wasClamped();
    }

    @Override
    public String clampNote() {
        return scene.autonomousCar().clampNote();
    }

    @Override
    public long clampedTicks() {
        return scene.autonomousCar().clampedTicks();
    }

    @Override
    public Observation observation() {
        return scene.autonomousCar().observation();
    }

    @Override
    public java.util.Set<sitcov.control.Sensor> sensors() {
        return scene.autonomousCar().sensors();
    }

    @Override
    public SelfReport selfReport() {
        return scene.autonomousCar().selfReport();
    }

    @Override
    public List<? extends Vehicle> movingCars() {
        return scene.movingCars();
    }

    @Override
    public boolean reachedTarget() {
        return scene.autonomousCar().hasReachedTarget();
    }

    @Override
    public ControllerFailure failure() {
        return scene.autonomousCar().failure();
    }
}
