package sitcov.seam;

import java.util.List;
import sitcov.control.Channel;
import sitcov.control.Vehicle;
import sitcov.geom.Box;

/**
 * A seam fault that hands the controller an older frame than this tick's ({@link #shown}, null for
 * this tick's own): every part of the observation from that frame, the tick itself this tick's (a
 * controller program echoes it). A part the frame did not remember, because the controller had not
 * read it before, is read live.
 */
abstract class FrameView extends ObservationView {
    /** The frame the controller is handed this tick, or null for the real one. */
    abstract Frame shown();

    @Override
    int parts() {
        return Part.ALL;
    }

    @Override
    public boolean acting() {
        return shown() != null;
    }

    private boolean has(int part) {
        Frame f = shown();
        return f != null && Part.has(f.parts, part);
    }

    @Override
    public double x() {
        return has(Part.POSE) ? shown().x : real.x();
    }

    @Override
    public double y() {
        return has(Part.POSE) ? shown().y : real.y();
    }

    @Override
    public double heading() {
        return has(Part.POSE) ? shown().heading : real.heading();
    }

    @Override
    public double speed() {
        return has(Part.POSE) ? shown().speed : real.speed();
    }

    @Override
    public List<Vehicle> traffic() {
        if (!has(Part.TRAFFIC)) {
            return real.traffic();
        }
        return shown().trafficView;
    }

    @Override
    public List<Box> obstacles() {
        if (!has(Part.OBSTACLES)) {
            return real.obstacles();
        }
        return shown().obstaclesView;
    }

    @Override
    public boolean holds(int junction) {
        Frame f = shown();
        return has(Part.RIGHT_OF_WAY) && junction >= 0 && junction < f.holds.length ? f.holds[junction]
                : super.holds(junction);
    }

    @Override
    public boolean wouldGrant(int junction) {
        Frame f = shown();
        return has(Part.RIGHT_OF_WAY) && junction >= 0 && junction < f.wouldGrant.length ? f.wouldGrant[junction]
                : super.wouldGrant(junction);
    }

    @Override
    public int cameraHits() {
        return has(Part.CAMERA) ? shown().cameraHits : real.cameraHits();
    }

    @Override
    public double cameraHitX(int hit) {
        return has(Part.CAMERA) ? shown().camera[2 * hit] : real.cameraHitX(hit);
    }

    @Override
    public double cameraHitY(int hit) {
        return has(Part.CAMERA) ? shown().camera[2 * hit + 1] : real.cameraHitY(hit);
    }

    @Override
    public int lidarHits() {
        return has(Part.LIDAR) ? shown().lidarHits : real.lidarHits();
    }

    @Override
    public double lidarHitX(int hit) {
        return has(Part.LIDAR) ? shown().lidar[2 * hit] : real.lidarHitX(hit);
    }

    @Override
    public double lidarHitY(int hit) {
        return has(Part.LIDAR) ? shown().lidar[2 * hit + 1] : real.lidarHitY(hit);
    }

    @Override
    public double channel(Channel channel) {
        return has(Part.channel(channel)) ? shown().channels[channel.ordinal()] : real.channel(channel);
    }
}
