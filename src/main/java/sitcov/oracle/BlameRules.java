package sitcov.oracle;

import sitcov.geom.Bearing;
import sitcov.control.SelfReport;
import sitcov.control.Vehicle;

/** Decides, by the named {@link Blame} rules, whether a contact with a moving car is the car's fault. */
final class BlameRules {
    private BlameRules() {
    }

    static Blame judge(Vehicle car, SelfReport said, Vehicle other, CentreLine centreLine, boolean carOverCentreLine) {
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
        if (headingDifference > 135 && !carOverCentreLine && !said.overtaking()) {
            return Blame.EXCUSED_OTHER_IN_WRONG_LANE;
        }
        return Blame.AT_FAULT;
    }
}
