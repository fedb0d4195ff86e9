package sitcov.seam;

import java.util.List;
import sitcov.control.Channel;
import sitcov.control.Observation;
import sitcov.control.RightOfWay;
import sitcov.control.Vehicle;
import sitcov.geom.Box;
import sitcov.world.RoadNetwork;
import sitcov.world.Target;

/**
 * A seam fault of the observation: a view over the real observation that changes the parts the
 * fault names and hands every other part through. Subclasses override what they change; the view is
 * made once a run and pointed at each tick's real observation.
 */
abstract non-sealed class ObservationView implements Observation, RightOfWay, Distortion {
    protected Observation real;
    protected long tick;

    @Override
    public void startTick(Observation now, long t) {
        this.real = now;
        this.tick = t;
        started();
    }

    /** The parts of the observation this fault changes ({@link Part}). */
    abstract int parts();

    /** Called once {@link #real} and {@link #tick} are this tick's. */
    void started() {
    }

    /** After the controller stepped: {@code consulted} is what it read (a fault that remembers frames keeps one here). */
    void endTick(Consults consulted) {
    }

    @Override
    public boolean acting() {
        return true;
    }

    @Override
    public long tick() {
        return real.tick();
    }

    @Override
    public double x() {
        return real.x();
    }

    @Override
    public double y() {
        return real.y();
    }

    @Override
    public double heading() {
        return real.heading();
    }

    @Override
    public double speed() {
        return real.speed();
    }

    @Override
    public RoadNetwork roads() {
        return real.roads();
    }

    @Override
    public Target target() {
        return real.target();
    }

    @Override
    public List<Vehicle> traffic() {
        return real.traffic();
    }

    @Override
    public List<Box> obstacles() {
        return real.obstacles();
    }

    @Override
    public RightOfWay rightOfWay() {
        return this;
    }

    @Override
    public boolean holds(int junction) {
        return real.rightOfWay().holds(junction);
    }

    @Override
    public boolean wouldGrant(int junction) {
        return real.rightOfWay().wouldGrant(junction);
    }

    @Override
    public int cameraHits() {
        return real.cameraHits();
    }

    @Override
    public double cameraHitX(int hit) {
        return real.cameraHitX(hit);
    }

    @Override
    public double cameraHitY(int hit) {
        return real.cameraHitY(hit);
    }

    @Override
    public int lidarHits() {
        return real.lidarHits();
    }

    @Override
    public double lidarHitX(int hit) {
        return real.lidarHitX(hit);
    }

    @Override
    public double lidarHitY(int hit) {
        return real.lidarHitY(hit);
    }

    @Override
    public double channel(Channel channel) {
        return real.channel(channel);
    }
}
