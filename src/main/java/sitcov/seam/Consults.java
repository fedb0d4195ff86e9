package sitcov.seam;

import java.util.Arrays;
import java.util.List;
import sitcov.control.Channel;
import sitcov.control.Observation;
import sitcov.control.RightOfWay;
import sitcov.control.Vehicle;
import sitcov.geom.Box;
import sitcov.world.RoadNetwork;
import sitcov.world.Target;

/**
 * The observation a controller is handed, recording which parts it reads in a tick: a part read is
 * a value the controller received, so a seam fault is reached and effective only on parts read. A
 * controller program reads what the protocol writes for it (the parts it asked for at hello); the
 * builtin car what it uses. The right-of-way signals are recorded junction by junction.
 */
final class Consults implements Observation, RightOfWay {
    private Observation source;
    private int mask;
    private int ever;
    private boolean[] asked = new boolean[0];
    private int[] askedList = new int[0];
    private int askedCount;

    /** Starts a tick in which the controller reads {@code now}. */
    void start(Observation now) {
        source = now;
        mask = 0;
        for (int i = 0; i < askedCount; i++) {
            asked[askedList[i]] = false;
        }
        askedCount = 0;
    }

    /** The parts read this tick. */
    int mask() {
        return mask;
    }

    /** The parts read in any tick so far (a fault that remembers frames keeps these). */
    int ever() {
        return ever;
    }

    /** How many junctions' signals were read this tick, and which ({@link #askedAt}). */
    int askedCount() {
        return askedCount;
    }

    int askedAt(int i) {
        return askedList[i];
    }

    private void read(int part) {
        mask |= part;
        ever |= part;
    }

    private void asked(int junction) {
        read(Part.RIGHT_OF_WAY);
        if (junction < 0) {
            return;
        }
        if (junction >= asked.length) {
            asked = Arrays.copyOf(asked, Math.max(junction + 1, 2 * asked.length));
            askedList = Arrays.copyOf(askedList, asked.length);
        }
        if (!asked[junction]) {
            asked[junction] = true;
            askedList[askedCount++] = junction;
        }
    }

    @Override
    public long tick() {
        return source.tick();
    }

    @Override
    public double x() {
        read(Part.POSE);
        return source.x();
    }

    @Override
    public double y() {
        read(Part.POSE);
        return source.y();
    }

    @Override
    public double heading() {
        read(Part.POSE);
        return source.heading();
    }

    @Override
    public double speed() {
        read(Part.POSE);
        return source.speed();
    }

    @Override
    public RoadNetwork roads() {
        return source.roads();
    }

    @Override
    public Target target() {
        return source.target();
    }

    @Override
    public List<Vehicle> traffic() {
        read(Part.TRAFFIC);
        return source.traffic();
    }

    @Override
    public List<Box> obstacles() {
        read(Part.OBSTACLES);
        return source.obstacles();
    }

    @Override
    public RightOfWay rightOfWay() {
        return this;
    }

    @Override
    public boolean holds(int junction) {
        asked(junction);
        return source.rightOfWay().holds(junction);
    }

    @Override
    public boolean wouldGrant(int junction) {
        asked(junction);
        return source.rightOfWay().wouldGrant(junction);
    }

    @Override
    public int cameraHits() {
        read(Part.CAMERA);
        return source.cameraHits();
    }

    @Override
    public double cameraHitX(int hit) {
        read(Part.CAMERA);
        return source.cameraHitX(hit);
    }

    @Override
    public double cameraHitY(int hit) {
        read(Part.CAMERA);
        return source.cameraHitY(hit);
    }

    @Override
    public int lidarHits() {
        read(Part.LIDAR);
        return source.lidarHits();
    }

    @Override
    public double lidarHitX(int hit) {
        read(Part.LIDAR);
        return source.lidarHitX(hit);
    }

    @Override
    public double lidarHitY(int hit) {
        read(Part.LIDAR);
        return source.lidarHitY(hit);
    }

    @Override
    public double channel(Channel channel) {
        read(Part.channel(channel));
        return source.channel(channel);
    }
}
