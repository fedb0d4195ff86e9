package sitcov.control;

import sitcov.geom.Bearing;
import sitcov.geom.Box;

/** What anyone may observe of a vehicle: where it is, where it faces, how fast it goes. */
public interface Vehicle {
    int id();

    /** The x of its front centre (the anchor). */
    double x();

    double y();

    /** Bearing in degrees (0 south, 90 east, 180 north, 270 west). */
    double heading();

    /** The x of the unit vector along its heading: {@code Bearing.dx(heading())}, which a car keeps rather than works out again. */
    default double headingDx() {
        return Bearing.dx(heading());
    }

    default double headingDy() {
        return Bearing.dy(heading());
    }

    /** Metres per tick. */
    double speed();

    double length();

    double width();

    /** Whether it is on the map; a moving car that left the network is inactive until it is replaced. */
    boolean isActive();

    /** Its footprint now, anchored at its front centre. */
    default Box footprint() {
        return Box.behind(x(), y(), heading(), length(), width());
    }
}
