package sitcov.protocol;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import sitcov.control.Channel;
import sitcov.control.Observation;
import sitcov.control.RightOfWay;
import sitcov.control.Vehicle;
import sitcov.geom.Box;
import sitcov.world.RoadNetwork;
import sitcov.world.Target;

/**
 * An observation rebuilt on the controller's side from an "observation" message: the same numbers
 * the world's observation held, so a controller served over the protocol decides exactly as it
 * would in process. Radar tracks become vehicles whose heading vector and footprint are worked out
 * from the heading as the world's are; LIDAR obstacles the same boxes. Reused tick after tick.
 */
final class WireObservation implements Observation, RightOfWay {
    private final RoadNetwork roads;
    private final Target target;
    private final boolean[] holds;
    private final boolean[] wouldGrant;
    private final List<Vehicle> traffic = new ArrayList<>();
    private final List<Box> obstacles = new ArrayList<>();
    private final List<Vehicle> trafficView = Collections.unmodifiableList(traffic);
    private final List<Box> obstaclesView = Collections.unmodifiableList(obstacles);
    private double[] camera = new double[0];
    private double[] lidar = new double[0];
    private final double[] channels = new double[Channel.values().length];
    private long tick;
    private double x;
    private double y;
    private double heading;
    private double speed;

    WireObservation(RoadNetwork roads, Target target) {
        this.roads = roads;
        this.target = target;
        this.holds = new boolean[roads.junctions().size()];
        this.wouldGrant = new boolean[roads.junctions().size()];
    }

    /** A radar track as the message gives it. */
    private record Track(int id, double x, double y, double heading, double speed, double length, double width)
            implements Vehicle {
        @Override
        public boolean isActive() {
            return true;
        }
    }

    /** Takes on the message's numbers; refused when one is missing or malformed. */
    void read(Message m) throws ProtocolException {
        m.expect("observation");
        tick = m.integer("tick");
        x = m.number("x");
        y = m.number("y");
        heading = m.number("heading");
        speed = m.number("speed");
        traffic.clear();
        List<Object> tracks = m.optionalList("traffic");
        for (int i = 0; i < tracks.size(); i++) {
            Message t = m.item(tracks, i, "traffic");
            traffic.add(new Track((int) t.integer("id"), t.number("x"), t.number("y"), t.number("heading"),
                    t.number("speed"), positive(t, "length"), positive(t, "width")));
        }
        obstacles.clear();
        List<Object> boxes = m.optionalList("obstacles");
        for (int i = 0; i < boxes.size(); i++) {
            Message b = m.item(boxes, i, "obstacles");
            obstacles.add(Box.centred(b.number("x"), b.number("y"), b.number("bearing"), positive(b, "length"),
                    positive(b, "width")));
        }
        java.util.Arrays.fill(holds, false);
        java.util.Arrays.fill(wouldGrant, false);
        List<Object> signals = m.list("junctions");
        for (int i = 0; i < signals.size(); i++) {
            Message j = m.item(signals, i, "junctions");
            long id = j.integer("id");
            if (id < 0 || id >= holds.length) {
                throw new ProtocolException("observation.junctions[" + i + "].id " + id + " is not a junction of the map");
            }
            holds[(int) id] = j.flag("holds");
            wouldGrant[(int) id] = j.flag("would_grant");
        }
        camera = points(m, "camera");
        lidar = points(m, "lidar");
        java.util.Arrays.fill(channels, Double.NaN);
        if (m.has("channels")) {
            Message c = m.object("channels");
            for (Map.Entry<String, Object> e : c.members().entrySet()) {
                Channel channel = Channel.ofWireName(e.getKey()).orElse(null);
                if (channel != null) {
                    channels[channel.ordinal()] = c.numberOrNaN(e.getKey());
                }
            }
        }
    }

    private static double positive(Message m, String name) throws ProtocolException {
        double v = m.number(name);
        if (!(v > 0)) {
            throw new ProtocolException("a " + name + " must be positive, got " + v);
        }
        return v;
    }

    private static double[] points(Message m, String name) throws ProtocolException {
        List<Object> items = m.optionalList(name);
        double[] xy = new double[2 * items.size()];
        for (int i = 0; i < items.size(); i++) {
            if (!(items.get(i) instanceof List<?> point) || point.size() != 2) {
                throw new ProtocolException("observation." + name + "[" + i + "] must be a point [x, y]");
            }
            @SuppressWarnings("unchecked")
            List<Object> p = (List<Object>) point;
            xy[2 * i] = m.numberAt(p, 0, name);
            xy[2 * i + 1] = m.numberAt(p, 1, name);
        }
        return xy;
    }

    @Override
    public long tick() {
        return tick;
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
    public RoadNetwork roads() {
        return roads;
    }

    @Override
    public Target target() {
        return target;
    }

    @Override
    public List<Vehicle> traffic() {
        return trafficView;
    }

    @Override
    public List<Box> obstacles() {
        return obstaclesView;
    }

    @Override
    public RightOfWay rightOfWay() {
        return this;
    }

    @Override
    public boolean holds(int junction) {
        return junction >= 0 && junction < holds.length && holds[junction];
    }

    @Override
    public boolean wouldGrant(int junction) {
        return junction >= 0 && junction < wouldGrant.length && wouldGrant[junction];
    }

    @Override
    public int cameraHits() {
        return camera.length / 2;
    }

    @Override
    public double cameraHitX(int hit) {
        return camera[2 * hit];
    }

    @Override
    public double cameraHitY(int hit) {
        return camera[2 * hit + 1];
    }

    @Override
    public int lidarHits() {
        return lidar.length / 2;
    }

    @Override
    public double lidarHitX(int hit) {
        return lidar[2 * hit];
    }

    @Override
    public double lidarHitY(int hit) {
        return lidar[2 * hit + 1];
    }

    /** The channel's value, NaN when the controller did not ask for it at hello. */
    @Override
    public double channel(Channel channel) {
        return channels[channel.ordinal()];
    }
}
