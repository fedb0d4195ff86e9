package sitcov.protocol;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import sitcov.control.Channel;
import sitcov.control.Command;
import sitcov.control.Observation;
import sitcov.control.RightOfWay;
import sitcov.control.RunEnd;
import sitcov.control.SelfReport;
import sitcov.control.Sensor;
import sitcov.control.Vehicle;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.vehicles.Dynamics;

/**
 * The messages of the protocol (experiments/controllers/README.md, "Testing your own controller", "The protocol"),
 * both ways:
 * what sitcov writes and reads, and what a controller writes and reads. One JSON object a line;
 * every message has a "type". Protocol 2 is protocol 1 with the tick echoed: each command names
 * the tick of the observation it answers, so that a command that answers another observation (a
 * second command written for one observation, read as the answer to the next) is caught the
 * moment it is read. Protocol 1, without the echo, is still accepted (deprecated).
 */
final class Wire {
    /** The newest protocol: the one sitcov offers first and the builtin car's server answers with. */
    static final int PROTOCOL = 2;
    /** Every protocol sitcov speaks, oldest first: its hello offers them, a controller's hello picks one. */
    static final List<Integer> PROTOCOLS = List.of(1, 2);
    /**
     * The sensors a controller may ask for at hello, each an observation member sent only to one
     * that asked: the radar's tracks ("traffic"), the LIDAR's parked cars ("obstacles"), the
     * camera's marking hits and the LIDAR's raw hits. Leaner lines are read faster: a controller
     * that needs no sensor asks for none.
     */
    static final List<String> SENSORS = names(EnumSet.allOf(Sensor.class));
    /** What a controller that says nothing of sensors gets: the objects its sensors report, no raw hits. */
    static final List<String> DEFAULT_SENSORS = names(Sensor.reported());
    /** The most runs sitcov steps together for one controller process (its hello's "max_batch"). */
    static final int MAX_BATCH = 64;

    private Wire() {
    }

    /** What a controller said at hello: who it is and what it wants in each observation. */
    record Hello(int protocol, String name, String version, Set<Channel> channels, boolean radar, boolean obstacles,
                 boolean camera, boolean lidar, boolean seededFaults, int batch) {
        /** A controller that takes one run at a time (no "batch" at hello). */
        Hello(int protocol, String name, String version, Set<Channel> channels, boolean radar, boolean obstacles,
              boolean camera, boolean lidar, boolean seededFaults) {
            this(protocol, name, version, channels, radar, obstacles, camera, lidar, seededFaults, 1);
        }

        /** A controller that has none of sitcov's seeded faults: it may report no fault activation. */
        Hello(int protocol, String name, String version, Set<Channel> channels, boolean radar, boolean obstacles,
              boolean camera, boolean lidar) {
            this(protocol, name, version, channels, radar, obstacles, camera, lidar, false);
        }

        /** The sensors it asked for: the parts of the observation sent to it. */
        Set<Sensor> sensors() {
            Set<Sensor> s = EnumSet.noneOf(Sensor.class);
            if (radar) {
                s.add(Sensor.RADAR);
            }
            if (obstacles) {
                s.add(Sensor.OBSTACLES);
            }
            if (camera) {
                s.add(Sensor.CAMERA);
            }
            if (lidar) {
                s.add(Sensor.LIDAR);
            }
            return s;
        }

        /** Whether each command must echo its observation's tick (protocol 2 and later). */
        boolean echoesTicks() {
            return protocol >= 2;
        }
    }

    // ---- sitcov -> controller

    static void sitcovHello(JsonWriter w, String sitcovVersion) {
        w.reset().beginObject().member("type", "hello").member("protocol", PROTOCOL);
        w.name("protocols").beginArray();
        for (int p : PROTOCOLS) {
            w.value(p);
        }
        w.endArray().member("sitcov", sitcovVersion);
        w.name("channels").beginArray();
        for (Channel c : Channel.values()) {
            w.value(c.wireName());
        }
        w.endArray();
        w.name("sensors").beginArray();
        for (String s : SENSORS) {
            w.value(s);
        }
        w.endArray();
        w.name("limits").beginObject().member("max_speed", Dynamics.MAX_SPEED).member("max_turn", Dynamics.MAX_TURN)
                .member("tick_seconds", sitcov.world.Dimensions.TICK_SECONDS).member("sensor_range", Observation.SENSOR_RANGE)
                .endObject();
        w.member("max_batch", MAX_BATCH);
        w.endObject();
    }

    static void observation(JsonWriter w, Observation now, Hello wants) {
        observation(w.reset(), now, wants, -1);
    }

    /**
     * Several runs' observations in one message, each tagged with its run's slot ({@code slots[i]}
     * for {@code now.get(i)}): {"type":"observations","items":[...]}.
     */
    static void observations(JsonWriter w, List<Observation> now, int[] slots, Hello wants) {
        w.reset().beginObject().member("type", "observations").name("items").beginArray();
        for (int i = 0; i < now.size(); i++) {
            observation(w, now.get(i), wants, slots[i]);
        }
        w.endArray().endObject();
    }

    /** One observation, tagged with its run's slot when {@code slot} is 0 or more, into {@code w} as it stands. */
    private static void observation(JsonWriter w, Observation now, Hello wants, int slot) {
        w.beginObject().member("type", "observation").member("tick", now.tick());
        if (slot >= 0) {
            w.member("run", slot);
        }
        w.member("x", now.x()).member("y", now.y()).member("heading", now.heading()).member("speed", now.speed());
        if (wants.radar()) {
            w.name("traffic").beginArray();
            List<Vehicle> traffic = now.traffic();
            for (int i = 0, n = traffic.size(); i < n; i++) {
                Vehicle v = traffic.get(i);
                w.beginObject().member("id", v.id()).member("x", v.x()).member("y", v.y()).member("heading", v.heading())
                        .member("speed", v.speed()).member("length", v.length()).member("width", v.width()).endObject();
            }
            w.endArray();
        }
        if (wants.obstacles()) {
            w.name("obstacles").beginArray();
            List<Box> obstacles = now.obstacles();
            for (int i = 0, n = obstacles.size(); i < n; i++) {
                Box b = obstacles.get(i);
                w.beginObject().member("x", b.centreX()).member("y", b.centreY()).member("bearing", b.bearing())
                        .member("length", b.length()).member("width", b.width()).endObject();
            }
            w.endArray();
        }
        w.name("junctions").beginArray();
        RightOfWay signals = now.rightOfWay();
        for (int j = 0, n = now.roads().junctions().size(); j < n; j++) {
            w.beginObject().member("id", j).member("holds", signals.holds(j))
                    .member("would_grant", signals.wouldGrant(j)).endObject();
        }
        w.endArray();
        if (wants.camera()) {
            w.name("camera").beginArray();
            for (int h = 0, n = now.cameraHits(); h < n; h++) {
                w.beginArray().value(now.cameraHitX(h)).value(now.cameraHitY(h)).endArray();
            }
            w.endArray();
        }
        if (wants.lidar()) {
            w.name("lidar").beginArray();
            for (int h = 0, n = now.lidarHits(); h < n; h++) {
                w.beginArray().value(now.lidarHitX(h)).value(now.lidarHitY(h)).endArray();
            }
            w.endArray();
        }
        if (!wants.channels().isEmpty()) {
            w.name("channels").beginObject();
            for (Channel c : wants.channels()) {
                w.member(c.wireName(), now.channel(c));
            }
            w.endObject();
        }
        w.endObject();
    }

    static void end(JsonWriter w, RunEnd how) {
        end(w, how, -1);
    }

    /** A run's end, tagged with its slot when {@code slot} is 0 or more (batches). */
    static void end(JsonWriter w, RunEnd how, int slot) {
        w.reset().beginObject().member("type", "end").member("outcome", how.outcome()).member("ticks", how.ticks());
        if (slot >= 0) {
            w.member("run", slot);
        }
        w.endObject();
    }

    // ---- controller -> sitcov

    /** A controller's hello, checked: a protocol sitcov speaks, channels and sensors sitcov has. */
    static Hello controllerHello(Message m) throws ProtocolException {
        m.expect("hello");
        long protocol = m.integer("protocol");
        if (protocol != (int) protocol || !PROTOCOLS.contains((int) protocol)) {
            throw new ProtocolException("it speaks protocol " + protocol + "; this sitcov speaks protocols " + spoken());
        }
        Set<Channel> channels = EnumSet.noneOf(Channel.class);
        List<Object> asked = m.optionalList("channels");
        for (Object name : asked) {
            Channel c = name instanceof String s ? Channel.ofWireName(s).orElse(null) : null;
            if (c == null) {
                throw new ProtocolException("it asks for the channel " + name + ", which sitcov does not have; the"
                        + " channels are " + String.join(", ", channelNames()));
            }
            channels.add(c);
        }
        List<Object> sensors = m.has("sensors") ? m.list("sensors") : List.copyOf(DEFAULT_SENSORS);
        for (Object sensor : sensors) {
            if (!SENSORS.contains(sensor)) {
                throw new ProtocolException("it asks for the sensor " + sensor + "; the sensors are "
                        + String.join(", ", SENSORS));
            }
        }
        String name = m.has("name") ? m.text("name") : "unnamed";
        String version = m.has("version") ? m.text("version") : "";
        long batch = m.has("batch") ? m.integer("batch") : 1;
        if (batch < 1) {
            throw new ProtocolException("its batch must be 1 or more (the most runs it takes in one message), got " + batch);
        }
        if (batch > 1 && protocol < 2) {
            throw new ProtocolException("batches (\"batch\": " + batch + ") need protocol 2: a batch's commands echo their ticks");
        }
        return new Hello((int) protocol, name, version, channels, sensors.contains("radar"), sensors.contains("obstacles"),
                sensors.contains("camera"), sensors.contains("lidar"), m.optionalFlag("faults"),
                (int) Math.min(batch, MAX_BATCH));
    }

    private static List<String> names(Set<Sensor> sensors) {
        return sensors.stream().map(Sensor::wireName).toList();
    }

    /** "1 and 2". */
    static String spoken() {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < PROTOCOLS.size(); i++) {
            b.append(i == 0 ? "" : i == PROTOCOLS.size() - 1 ? " and " : ", ").append(PROTOCOLS.get(i));
        }
        return b.toString();
    }

    private static List<String> channelNames() {
        List<String> names = new ArrayList<>();
        for (Channel c : Channel.values()) {
            names.add(c.wireName());
        }
        return names;
    }

    /**
     * Reads the command that answers the observation of {@code tick} into {@code out} (cleared), and
     * reports its fault activations into {@code faults}: ids it reached this tick, and how many times
     * each was effective. With {@code echoesTicks} (protocol 2) the command must name {@code tick};
     * it is checked before anything of the command is taken, so that a command meant for another
     * observation changes nothing.
     */
    static void command(Message m, long tick, boolean echoesTicks, Command out, FaultSwitchboard faults)
            throws ProtocolException {
        command(m, tick, echoesTicks, true, out, faults);
    }

    /**
     * As above, for a controller that said at hello whether it has sitcov's seeded faults
     * ({@code seededFaults}): one that did not may report no fault activation.
     */
    static void command(Message m, long tick, boolean echoesTicks, boolean seededFaults, Command out,
                        FaultSwitchboard faults) throws ProtocolException {
        m.expect("command");
        if (echoesTicks) {
            checkTick(m, tick);
        }
        // a speed asked for outright moves the car to the bit; otherwise the change is added to the speed
        if (m.has("speed")) {
            out.speed(m.number("speed"));
        } else {
            out.speedChange(m.number("speed_change"));
        }
        out.steering(m.number("steering"));
        List<Object> releases = m.optionalList("release");
        for (int i = 0; i < releases.size(); i++) {
            out.release(junctionId(m.wholeAt(releases, i, "release")));
        }
        List<Object> claims = m.optionalList("claim");
        for (int i = 0; i < claims.size(); i++) {
            out.claim(junctionId(m.wholeAt(claims, i, "claim")));
        }
        if (m.has("report")) {
            Message r = m.object("report");
            SelfReport report = out.report();
            report.overtaking(r.optionalFlag("overtaking")).crossingJunction(r.optionalFlag("crossing_junction"))
                    .waitingAtJunction(r.optionalFlag("waiting")).stage(r.optionalText("stage"))
                    .limitedBy(r.optionalText("limited_by")).steeredBy(r.optionalText("steered_by"));
            String lane = r.optionalText("lane");
            report.lane(lane == null ? null : compass(lane, "command.report.lane"));
        }
        if (m.has("faults")) {
            if (!seededFaults) {
                throw new ProtocolException("it reported fault activations, but its hello did not say it has sitcov's"
                        + " seeded faults (\"faults\": true); only such a controller, like the builtin car served by"
                        + " 'controller builtin', may report them");
            }
            Message f = m.object("faults");
            List<Object> reached = f.optionalList("reached");
            for (int i = 0; i < reached.size(); i++) {
                faults.reached(fault(f.wholeAt(reached, i, "reached")));
            }
            List<Object> effective = f.optionalList("effective");
            for (int i = 0; i < effective.size(); i++) {
                if (!(effective.get(i) instanceof List<?> pair) || pair.size() != 2) {
                    throw new ProtocolException("command.faults.effective[" + i + "] must be a pair [id, count]");
                }
                @SuppressWarnings("unchecked")
                List<Object> idCount = (List<Object>) pair;
                Fault fault = fault(f.wholeAt(idCount, 0, "effective[" + i + "]"));
                long count = f.wholeAt(idCount, 1, "effective[" + i + "]");
                for (long k = 0; k < count; k++) {
                    faults.effective(fault);
                }
            }
        }
    }

    /** A protocol-2 command's tick: present, whole, and the observation's. */
    private static void checkTick(Message m, long tick) throws ProtocolException {
        if (!m.has("tick")) {
            throw new ProtocolException("command.tick is missing: with protocol 2 a command echoes the tick of the"
                    + " observation it answers (" + tick + ")");
        }
        long answered = m.integer("tick");
        if (answered != tick) {
            throw new ProtocolException("the command answers tick " + answered + ", the observation was tick " + tick
                    + (answered < tick ? " (a command written for an earlier observation: each observation gets"
                    + " exactly one command)" : ""));
        }
    }

    private static int junctionId(long id) throws ProtocolException {
        if (id < 0 || id > Integer.MAX_VALUE) {
            throw new ProtocolException("a junction id must be 0 or more, got " + id);
        }
        return (int) id;
    }

    private static Fault fault(long id) throws ProtocolException {
        if (id < 0 || id >= Fault.values().length) {
            throw new ProtocolException("there is no fault " + id + " (ids are 0.." + (Fault.values().length - 1) + ")");
        }
        return Fault.ofId((int) id);
    }

    static String name(Compass c) {
        return c.name().toLowerCase(Locale.ROOT);
    }

    static Compass compass(String name, String where) throws ProtocolException {
        for (Compass c : Compass.values()) {
            if (name(c).equals(name)) {
                return c;
            }
        }
        throw new ProtocolException(where + " must be north, east, south or west, got " + name);
    }
}
