package sitcov.protocol;

import sitcov.control.Command;
import sitcov.control.Controller;
import sitcov.control.ControllerFailure;
import sitcov.control.Observation;
import sitcov.control.RunEnd;
import sitcov.faults.FaultSwitchboard;

/**
 * A controller program, seen from the world: each tick it sends the observation over its session,
 * reads the command into the world's {@link Command}, and replays the fault activations the
 * command reports into the run's switchboard (at the same tick, so the run records them as an
 * in-process run would). With protocol 2 the command must echo the observation's tick: a second
 * command written for one observation is read as the answer to the next one, and its tick, the
 * previous observation's, ends the run with a {@code CONTROLLER_ERROR} naming both ticks. Only the
 * tick is checked, never whether a line is already waiting before an observation is sent: that
 * would depend on how fast the controller wrote, and the tick a run fails at would not be
 * deterministic.
 */
final class ProxyController implements Controller {
    private final Session session;
    private final FaultSwitchboard faults;
    private final long tickTimeoutMillis;

    ProxyController(Session session, FaultSwitchboard faults, long tickTimeoutMillis) {
        this.session = session;
        this.faults = faults;
        this.tickTimeoutMillis = tickTimeoutMillis;
    }

    @Override
    public void step(Observation now, Command out) {
        String line = session.step(now, tickTimeoutMillis);
        try {
            Wire.command(Message.parse(line), now.tick(), session.hello().echoesTicks(), session.hello().seededFaults(), out,
                    faults);
        } catch (ProtocolException e) {
            throw session.error("at tick " + now.tick() + " it wrote " + Message.shorten(line) + ": " + e.getMessage());
        }
    }

    @Override
    public java.util.Set<sitcov.control.Sensor> sensors() {
        return session.hello() == null ? java.util.Set.of() : session.hello().sensors();
    }

    @Override
    public void end(RunEnd how) {
        session.end(how);
    }

    /** A controller that could not be started: the run ends at its first tick with its reason. */
    static Controller failed(String why) {
        return new Controller() {
            @Override
            public void step(Observation now, Command out) {
                throw new ControllerFailure(ControllerFailure.Kind.ERROR, why);
            }

            @Override
            public java.util.Set<sitcov.control.Sensor> sensors() {
                return java.util.Set.of(); // it never took an observation
            }
        };
    }
}
