package sitcov.seam;

import sitcov.control.Vehicle;

/** A radar track as a remembered frame keeps it: the vehicle's values at that tick, not the vehicle. */
final class Track implements Vehicle {
    private int id;
    private double x;
    private double y;
    private double heading;
    private double speed;
    private double length;
    private double width;

    void set(Vehicle v) {
        id = v.id();
        x = v.x();
        y = v.y();
        heading = v.heading();
        speed = v.speed();
        length = v.length();
        width = v.width();
    }

    @Override
    public int id() {
        return id;
    }

    @Override
    public double x() {
        return x;
    }

    @Override
    public double y() {
        return y;
    }

    @Override
    public double heading() {
        return heading;
    }

    @Override
    public double speed() {
        return speed;
    }

    @Override
    public double length() {
        return length;
    }

    @Override
    public double width() {
        return width;
    }

    @Override
    public boolean isActive() {
        return true;
    }
}
