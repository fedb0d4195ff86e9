package sitcov.protocol;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import sitcov.control.Command;
import sitcov.control.Controller;
import sitcov.control.ControllerFactory;
import sitcov.control.RunEnd;
import sitcov.control.RunStart;
import sitcov.engine.RandomStreams;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.faults.SeededControllerFactory;
import sitcov.world.RoadNetwork;

/**
 * The controller's side of the protocol: serves any {@link ControllerFactory} over a pair of
 * streams (stdin and stdout for {@code sitcov controller builtin}). Answers sitcov's hello, starts
 * a controller at each reset on the map the message carries (a controller with seeded faults is
 * handed a switchboard with the faults the reset names), answers each observation with the
 * controller's command and the fault activations of the tick, and tells it the end. Returns at
 * the end of its input.
 */
public final class ControllerServer {
    private final ControllerFactory controllers;
    private final String name;
    private final String version;
    private final Set<Fault> extraFaults;
    private final int newestProtocol;
    private final int batch;

    /**
     * A server that speaks the newest protocol sitcov offers, up to {@link Wire#PROTOCOL}.
     *
     * @param extraFaults faults switched on in every run besides those the reset names
     */
    public ControllerServer(ControllerFactory controllers, String name, String version, Set<Fault> extraFaults) {
        this(controllers, name, version, extraFaults, Wire.PROTOCOL);
    }

    /**
     * @param newestProtocol the newest protocol it answers with (1: the deprecated protocol without
     *                       the tick echo, for checking that runs do not depend on it)
     */
    public ControllerServer(ControllerFactory controllers, String name, String version, Set<Fault> extraFaults,
                            int newestProtocol) {
        this(controllers, name, version, extraFaults, newestProtocol, 1);
    }

    /** @param batch the most runs it takes in one message (batched lockstep; 1: one at a time) */
    public ControllerServer(ControllerFactory controllers, String name, String version, Set<Fault> extraFaults,
                            int newestProtocol, int batch) {
        if (batch < 1 || (batch > 1 && newestProtocol < 2)) {
            throw new IllegalArgumentException("batch " + batch + " with protocol " + newestProtocol);
        }
        this.batch = batch;
        if (!Wire.PROTOCOLS.contains(newestProtocol)) {
            throw new IllegalArgumentException("protocol " + newestProtocol + "; the protocols are " + Wire.spoken());
        }
        this.controllers = controllers;
        this.name = name;
        this.version = version;
        this.extraFaults = Set.copyOf(extraFaults);
        this.newestProtocol = newestProtocol;
    }

    /** Serves until the input ends; a message that breaks the protocol ends it with the exception. */
    public void serve(InputStream in, OutputStream out) throws IOException, ProtocolException {
        Lines lines = new Lines(in, out);
        JsonWriter w = new JsonWriter();
        String first = lines.read();
        if (first == null) {
            return;
        }
        int protocol = protocol(Message.parse(first).expect("hello"));
        // the builtin car works from its own camera and LIDAR on the map, and from the objects its sensors report
        ControllerWire.hello(w, protocol, name, version, Set.of(), Wire.DEFAULT_SENSORS, true, protocol >= 2 ? batch : 1);
        lines.write(w);
        Run run = null;
        java.util.Map<Long, Run> slots = new java.util.HashMap<>();
        Command command = new Command();
        for (String line = lines.read(); line != null; line = lines.read()) {
            Message m = Message.parse(line);
            switch (m.type()) {
                case "reset" -> {
                    if (m.has("run")) {
                        slots.put(m.integer("run"), start(ResetMessage.read(m)));
                    } else {
                        run = start(ResetMessage.read(m));
                    }
                }
                case "observations" -> {
                    List<Object> items = m.list("items");
                    w.reset().beginObject().member("type", "commands").name("items").beginArray();
                    for (int i = 0; i < items.size(); i++) {
                        Message item = m.messageAt(items, i, "items");
                        Run r = slots.get(item.integer("run"));
                        if (r == null) {
                            throw new ProtocolException("an observation of run " + item.integer("run") + " before its reset");
                        }
                        r.observation.read(item);
                        r.tick = r.observation.tick();
                        command.clear();
                        r.controller.step(r.observation, command);
                        ControllerWire.command(w, r.tick, (int) item.integer("run"), command, r.activity);
                    }
                    w.endArray().endObject();
                    lines.write(w);
                }
                case "observation" -> {
                    if (run == null) {
                        throw new ProtocolException("an observation before any reset");
                    }
                    run.observation.read(m);
                    run.tick = run.observation.tick();
                    command.clear();
                    run.controller.step(run.observation, command);
                    ControllerWire.command(w, protocol >= 2 ? run.tick : -1, command, run.activity);
                    lines.write(w);
                }
                case "end" -> {
                    if (m.has("run")) {
                        Run ended = slots.remove(m.integer("run"));
                        if (ended != null) {
                            ended.controller.end(new RunEnd(m.text("outcome"), m.integer("ticks")));
                        }
                    } else if (run != null) {
                        run.controller.end(new RunEnd(m.text("outcome"), m.integer("ticks")));
                        run = null;
                    }
                }
                default -> throw new ProtocolException("unknown message type \"" + m.type() + "\"");
            }
        }
    }

    /**
     * The newest protocol both speak: sitcov's hello offers its protocols in "protocols" (a sitcov
     * of protocol 1 only names its one protocol in "protocol").
     */
    private int protocol(Message hello) throws ProtocolException {
        List<Object> offered = hello.has("protocols") ? hello.list("protocols") : List.of(hello.integer("protocol"));
        int best = 0;
        for (int i = 0; i < offered.size(); i++) {
            long p = hello.wholeAt(offered, i, "protocols");
            if (p >= 1 && p <= newestProtocol && Wire.PROTOCOLS.contains((int) p) && p > best) {
                best = (int) p;
            }
        }
        if (best == 0) {
            throw new ProtocolException("sitcov speaks protocols " + offered + "; this controller speaks protocols 1 to "
                    + newestProtocol);
        }
        return best;
    }

    /** One run on the controller's side: its controller, the rebuilt observation, its faults. */
    private static final class Run {
        Controller controller;
        WireObservation observation;
        FaultActivity activity;
        long tick;
    }

    private Run start(ResetMessage reset) {
        Run run = new Run();
        Set<Fault> faults = EnumSet.noneOf(Fault.class);
        faults.addAll(reset.faults());
        faults.addAll(extraFaults);
        FaultSwitchboard switchboard = new FaultSwitchboard(faults, () -> run.tick);
        RoadNetwork roads = RoadNetwork.of(reset.map().layout());
        run.observation = new WireObservation(roads, reset.map().layout().target().orElseThrow());
        run.activity = new FaultActivity(switchboard);
        RunStart start = new RunStart(reset.map(), reset.internalSeed(), new RandomStreams(reset.internalSeed()),
                () -> run.tick);
        run.controller = controllers instanceof SeededControllerFactory seeded ? seeded.start(start, switchboard)
                : controllers.start(start);
        return run;
    }
}
