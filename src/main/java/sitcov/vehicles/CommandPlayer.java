package sitcov.vehicles;

import sitcov.control.Command;
import sitcov.control.Controller;
import sitcov.control.ControllerFactory;
import sitcov.control.ControllerFailure;
import sitcov.control.Observation;

/**
 * Drives the car from a {@link CommandLog} instead of its controller: each tick the logged command,
 * so that the world, deterministic given the commands, runs the logged run again tick for tick. A
 * tick the world clamped is asked as it was asked (the world clamps it again, noting it as before);
 * any other is asked for the speed it was given outright, which the world carries out to the bit. A
 * logged failure is thrown at its tick; a tick past the log's end is a failure naming it.
 */
public final class CommandPlayer implements Controller {
    private CommandLog log;
    private int tick;
    private int clamp;
    private int request;
    private int reportAt;
    private CommandLog.Report report = CommandLog.Report.NOTHING;

    public CommandPlayer(CommandLog log) {
        this.log = log;
    }

    /** A factory whose every run is driven by {@code log}; its runs can be copied, as the player's state is the run's. */
    public static ControllerFactory factory(CommandLog log) {
        return new ControllerFactory() {
            @Override
            public Controller start(sitcov.control.RunStart run) {
                return new CommandPlayer(log);
            }

            @Override
            public boolean copyable() {
                return true;
            }
        };
    }

    /** The sensors the recorded run's controller took: a replay's observation is the recorded run's. */
    @Override
    public java.util.Set<sitcov.control.Sensor> sensors() {
        return log.sensors();
    }

    @Override
    public void step(Observation now, Command out) {
        int k = tick++;
        if (k == log.failedAt()) {
            throw new ControllerFailure(log.failureKind(), log.failureMessage());
        }
        if (k >= log.ticks()) {
            throw new ControllerFailure(ControllerFailure.Kind.ERROR, "the recording ends after " + log.ticks()
                    + " ticks, and the run went on to tick " + k);
        }
        while (request < log.requests() && log.requestTick(request) == k) {
            if (log.isClaim(request)) {
                out.claim(log.requestJunction(request));
            } else {
                out.release(log.requestJunction(request));
            }
            request++;
        }
        while (reportAt < log.reports() && log.reportTick(reportAt) <= k) {
            report = log.report(reportAt++);
        }
        report.applyTo(out.report());
        if (clamp < log.clamps() && log.clampTick(clamp) == k) {
            double asked = log.askedSpeed(clamp);
            // NaN: the controller asked for no speed at all, neither a change nor a speed outright
            out.speed(asked).speedChange(Double.isNaN(asked) ? Double.NaN : 0).steering(log.askedSteering(clamp));
            clamp++;
        } else {
            out.speed(log.speed(k)).steering(log.steering(k));
        }
    }
}
