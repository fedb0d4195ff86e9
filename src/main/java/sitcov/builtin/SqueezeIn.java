package sitcov.builtin;

import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.vehicles.Dynamics;
import sitcov.vehicles.Lanes;
import sitcov.world.Dimensions;

/**
 * Squeezing in at a Target too close past a row of parked cars for the tight return: out in the
 * other lane, the car heads for the Target once its front is past the row's end, turning in only
 * as far as keeps its tail clear of the row (it turns about its rear axle, so the tail swings
 * towards the row), as a driver squeezes in ahead of a parked car.
 */
final class SqueezeIn {
    /** How far past the row's end the car's front goes before it turns in. */
    static final double CLEARANCE = 0.7;
    /** How far the car keeps its tail from the row's end it saw: the LIDAR sees that end only to a few tenths. */
    static final double TAIL_MARGIN = 0.6;
    /** Where the side of a row of parked cars lies, from the lane's centre towards the other lane, with a margin. */
    static final double ROW_FACE = 1.0;
    /** How deep, from its side to the kerb, the row is taken to be. */
    static final double ROW_DEPTH = 3;

    private BuiltinCar car;
    private Compass lane;
    /** Where the row ends, as a coordinate along the road, so it stays put while the car moves; NaN when not squeezing in. */
    private double rowEndAlong = Double.NaN;

    SqueezeIn(BuiltinCar car) {
        this.car = car;
    }

    /** Starts squeezing in along {@code lane} past a row that ends {@code rowEnd} metres ahead. */
    void begin(Compass lane, double rowEnd) {
        this.lane = lane;
        this.rowEndAlong = along() + rowEnd * Lanes.forwardSign(lane);
    }

    boolean isOn() {
        return !Double.isNaN(rowEndAlong);
    }

    void end() {
        rowEndAlong = Double.NaN;
    }

    /**
     * Heads straight for the Target, slowing to stop on it; false when the Target was missed
     * (passed beyond reach), and the manoeuvre is over.
     */
    boolean steer(Intent intent, double laneCentre) {
        var target = car.target().position();
        if (LaneFrame.u(lane, car.x(), car.y(), target.x(), target.y()) < -TargetSeeker.CAPTURE_DISTANCE) {
            return false;
        }
        intent.stopWithin(target.distanceTo(car.x(), car.y()), "overtaking");
        double rowEnd = (rowEndAlong - along()) * Lanes.forwardSign(lane);
        double face = laneCentre + ROW_FACE;
        double heading = car.heading();
        double toward = Bearing.turn(heading, Bearing.between(car.x(), car.y(), target.x(), target.y()));
        double step = Math.max(-Dynamics.MAX_TURN, Math.min(Dynamics.MAX_TURN, toward));
        double speed = Math.min(car.speed() + Dynamics.ACCELERATION, Overtaker.TIGHT_SPEED);
        // it turns in only as far as keeps the tail clear of the row's end, straightening while it is not
        double bearing = heading + step;
        if (!tailClear(bearing, speed, rowEnd, face)) {
            bearing = tailClear(heading, speed, rowEnd, face) ? heading : lane.bearing();
        }
        intent.steer(bearing, "overtaking");
        return true;
    }

    /**
     * Whether the car's footprint after turning to {@code bearing} (about its rear axle) and moving
     * {@code speed} keeps clear of the row: everything short of its end and beyond its side, with margins.
     */
    private boolean tailClear(double bearing, double speed, double rowEnd, double face) {
        double pivot = BuiltinCar.REAR_AXLE;
        double nx = car.x() - pivot * Bearing.dx(car.heading()) + (pivot + speed) * Bearing.dx(bearing);
        double ny = car.y() - pivot * Bearing.dy(car.heading()) + (pivot + speed) * Bearing.dy(bearing);
        Box next = Box.behind(nx, ny, bearing, Dimensions.AUTONOMOUS_CAR_LENGTH, Dimensions.AUTONOMOUS_CAR_WIDTH);
        double u = rowEnd + TAIL_MARGIN;
        double v = face - ROW_DEPTH / 2;
        Box row = Box.behind(LaneFrame.x(lane, car.x(), u, v), LaneFrame.y(lane, car.y(), u, v), lane.bearing(),
                Overtaker.PARKED_CAR_LENGTH, ROW_DEPTH);
        return !next.overlaps(row);
    }

    private double along() {
        return Lanes.along(lane, car.x(), car.y());
    }
}
