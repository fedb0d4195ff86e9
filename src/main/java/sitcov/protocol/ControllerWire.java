package sitcov.protocol;

import java.util.List;
import java.util.Set;
import sitcov.control.Channel;
import sitcov.control.Command;
import sitcov.control.SelfReport;

/**
 * The controller's side of the protocol (experiments/controllers/README.md, "The protocol"): the hello and the
 * commands a
 * controller writes, as the builtin car served over the protocol writes them. sitcov's side, and the
 * reading of both, is {@link Wire}.
 */
final class ControllerWire {
    private ControllerWire() {
    }

    static void hello(JsonWriter w, int protocol, String name, String version, Set<Channel> channels,
                                List<String> sensors) {
        hello(w, protocol, name, version, channels, sensors, false);
    }

    /** A hello that says, with {@code seededFaults}, that the controller has sitcov's seeded faults and reports them. */
    static void hello(JsonWriter w, int protocol, String name, String version, Set<Channel> channels,
                                List<String> sensors, boolean seededFaults) {
        hello(w, protocol, name, version, channels, sensors, seededFaults, 1);
    }

    /** The same, taking up to {@code batch} runs in one message (written only when more than 1). */
    static void hello(JsonWriter w, int protocol, String name, String version, Set<Channel> channels,
                                List<String> sensors, boolean seededFaults, int batch) {
        w.reset().beginObject().member("type", "hello").member("protocol", protocol).member("name", name)
                .member("version", version);
        if (batch > 1) {
            w.member("batch", batch);
        }
        if (seededFaults) {
            w.member("faults", true);
        }
        w.name("channels").beginArray();
        for (Channel c : channels) {
            w.value(c.wireName());
        }
        w.endArray().name("sensors").beginArray();
        for (String sensor : sensors) {
            w.value(sensor);
        }
        w.endArray().endObject();
    }

    /**
     * A command, with the fault activations since the last one ({@code activity}); with protocol 2
     * it names the tick it answers ({@code tick}; protocol 1: pass a negative tick, none is written).
     */
    static void command(JsonWriter w, long tick, Command c, FaultActivity activity) {
        command(w.reset(), tick, -1, c, activity);
    }

    /** A command into {@code w} as it stands, naming its run's slot when {@code slot} is 0 or more (an item of a batch's commands). */
    static void command(JsonWriter w, long tick, int slot, Command c, FaultActivity activity) {
        w.beginObject().member("type", "command");
        if (tick >= 0) {
            w.member("tick", tick);
        }
        if (slot >= 0) {
            w.member("run", slot);
        }
        if (Double.isNaN(c.speed())) {
            w.member("speed_change", c.speedChange());
        } else {
            w.member("speed", c.speed());
        }
        w.member("steering", c.steering());
        w.name("claim").beginArray();
        for (int i = 0; i < c.claimCount(); i++) {
            w.value(c.claimAt(i));
        }
        w.endArray();
        w.name("release").beginArray();
        for (int i = 0; i < c.releaseCount(); i++) {
            w.value(c.releaseAt(i));
        }
        w.endArray();
        SelfReport r = c.report();
        w.name("report").beginObject().member("overtaking", r.overtaking())
                .member("crossing_junction", r.crossingJunction()).member("waiting", r.waitingAtJunction())
                .member("lane", r.lane() == null ? null : Wire.name(r.lane())).member("stage", r.stage())
                .member("limited_by", r.limitedBy()).member("steered_by", r.steeredBy()).endObject();
        activity.write(w);
        w.endObject();
    }
}
