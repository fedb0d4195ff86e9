package sitcov.oracle;

import sitcov.geom.Bearing;
import sitcov.control.Vehicle;

/**
 * Decides, by the named {@link Blame} rules, whether a contact with a moving car is the car's fault,
 * from what anyone sees of both: poses, speeds, footprints.
 */
final class BlameRules {
    private BlameRules() {
    }

    /**
     * {@code carOverCentreLine} is whether the car's footprint is over the centre line at all, excused
     * or not: a car out in the other lane, even passing a parked car with good reason, did not keep to
     * its own lane, so a car coming the other way there is not in the wrong lane.
     */
    static Blame judge(Vehicle car, Vehicle other, CentreLine centreLine, boolean carOverCentreLine) {
        if (car.speed() == 0) {
            return Blame.EXCUSED_STANDING_STILL;
        }
        double headingDifference = Math.abs(Bearing.turn(car.heading(), other.heading()));
        double behind = (other.x() - car.x()) * car.headingDx() + (other.y() - car.y()) * car.headingDy();
        if (headingDifference < 45 && behind < 0 && other.speed() > car.speed()) {
            return Blame.EXCUSED_HIT_FROM_BEHIND;
        }
        if (centreLine.touches(other.footprint())) {
            return Blame.EXCUSED_OTHER_ON_CENTRE_LINE;
        }
        if (headingDifference > 135 && !carOverCentreLine) {
            return Blame.EXCUSED_OTHER_IN_WRONG_LANE;
        }
        return Blame.AT_FAULT;
    }
}
