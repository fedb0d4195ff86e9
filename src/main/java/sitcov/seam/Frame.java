package sitcov.seam;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import sitcov.control.Channel;
import sitcov.control.Observation;
import sitcov.control.Vehicle;
import sitcov.engine.ReadOnlyView;
import sitcov.geom.Box;

/**
 * An observation remembered: the values of one tick's pose, radar tracks, parked cars, right-of-way
 * signals, and of the camera's and LIDAR's hits and the ground-truth channels the controller had read
 * by then (working them out for a controller that never reads them would cost every run). A part not
 * remembered is read live ({@link FrameView}). Its arrays are reused from one remembering to the next.
 */
final class Frame {
    /** What every frame keeps: the parts any controller receives without asking. */
    static final int ALWAYS = Part.POSE | Part.TRAFFIC | Part.OBSTACLES | Part.RIGHT_OF_WAY;

    int parts;
    double x;
    double y;
    double heading;
    double speed;
    private List<Track> pool = new ArrayList<>();
    List<Vehicle> traffic = new ArrayList<>();
    List<Box> obstacles = new ArrayList<>();
    List<Vehicle> trafficView = new ReadOnlyView<>(traffic);
    List<Box> obstaclesView = new ReadOnlyView<>(obstacles);
    boolean[] holds = new boolean[0];
    boolean[] wouldGrant = new boolean[0];
    double[] camera = new double[0];
    int cameraHits;
    double[] lidar = new double[0];
    int lidarHits;
    double[] channels = new double[Channel.values().length];

    /** Remembers {@code now}: the parts of {@link #ALWAYS} and those of {@code read}. */
    void remember(Observation now, int read) {
        parts = ALWAYS | read;
        x = now.x();
        y = now.y();
        heading = now.heading();
        speed = now.speed();
        rememberTraffic(now.traffic());
        obstacles.clear();
        obstacles.addAll(now.obstacles());
        int junctions = now.roads().junctions().size();
        if (holds.length != junctions) {
            holds = new boolean[junctions];
            wouldGrant = new boolean[junctions];
        }
        for (int j = 0; j < junctions; j++) {
            holds[j] = now.rightOfWay().holds(j);
            wouldGrant[j] = now.rightOfWay().wouldGrant(j);
        }
        if (Part.has(parts, Part.CAMERA)) {
            cameraHits = now.cameraHits();
            camera = room(camera, 2 * cameraHits);
            for (int h = 0; h < cameraHits; h++) {
                camera[2 * h] = now.cameraHitX(h);
                camera[2 * h + 1] = now.cameraHitY(h);
            }
        }
        if (Part.has(parts, Part.LIDAR)) {
            lidarHits = now.lidarHits();
            lidar = room(lidar, 2 * lidarHits);
            for (int h = 0; h < lidarHits; h++) {
                lidar[2 * h] = now.lidarHitX(h);
                lidar[2 * h + 1] = now.lidarHitY(h);
            }
        }
        for (Channel c : Channel.values()) {
            if (Part.has(parts, Part.channel(c))) {
                channels[c.ordinal()] = now.channel(c);
            }
        }
    }

    private void rememberTraffic(List<Vehicle> now) {
        traffic.clear();
        for (int i = 0, n = now.size(); i < n; i++) {
            if (i == pool.size()) {
                pool.add(new Track());
            }
            Track t = pool.get(i);
            t.set(now.get(i));
            traffic.add(t);
        }
    }

    private static double[] room(double[] values, int needed) {
        return values.length >= needed ? values : Arrays.copyOf(values, Math.max(needed, 2 * values.length));
    }
}
