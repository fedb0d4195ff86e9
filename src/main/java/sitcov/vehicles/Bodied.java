package sitcov.vehicles;

import sitcov.control.Vehicle;
import sitcov.geom.Box;

/** A vehicle whose pose and speed are those of a {@link Body}: what it shows is what the body holds. */
public interface Bodied extends Vehicle {
    Body body();

    @Override
    default double x() {
        return body().x();
    }

    @Override
    default double y() {
        return body().y();
    }

    @Override
    default double heading() {
        return body().heading();
    }

    @Override
    default double headingDx() {
        return body().headingDx();
    }

    @Override
    default double headingDy() {
        return body().headingDy();
    }

    @Override
    default double speed() {
        return body().speed();
    }

    @Override
    default Box footprint() {
        return body().footprint(length(), width());
    }
}
