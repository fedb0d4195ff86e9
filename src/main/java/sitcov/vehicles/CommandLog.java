package sitcov.vehicles;

import java.util.Arrays;
import sitcov.control.ControllerFailure;

/**
 * What the world carried out of the car's commands in one run, one entry a tick its controller was
 * asked: the speed and steering after clamping (and, on a tick the world clamped, what was asked),
 * the junctions let go of and asked for, the self-report where it changed, and the controller's
 * failure if it failed. The world is deterministic given these, so they are the run: a
 * {@link CommandPlayer} drives the car from them instead of the controller. Kept in arrays that grow
 * by doubling, so logging a tick allocates nothing (a changed self-report excepted); no final field,
 * as a checkpoint copies it with the run ({@link sitcov.engine.ModelCopy}).
 */
public final class CommandLog {
    /** What a controller said of itself in a tick, as values. */
    public record Report(boolean overtaking, boolean crossingJunction, boolean waitingAtJunction,
                         sitcov.geom.Compass lane, String stage, String limitedBy, String steeredBy) {
        /** What a controller that says nothing reports. */
        public static final Report NOTHING = new Report(false, false, false, null, null, null, null);

        static Report of(sitcov.control.SelfReport r) {
            return new Report(r.overtaking(), r.crossingJunction(), r.waitingAtJunction(), r.lane(), r.stage(),
                    r.limitedBy(), r.steeredBy());
        }

        boolean sameAs(sitcov.control.SelfReport r) {
            return overtaking == r.overtaking() && crossingJunction == r.crossingJunction()
                    && waitingAtJunction == r.waitingAtJunction() && lane == r.lane()
                    && java.util.Objects.equals(stage, r.stage()) && java.util.Objects.equals(limitedBy, r.limitedBy())
                    && java.util.Objects.equals(steeredBy, r.steeredBy());
        }

        void applyTo(sitcov.control.SelfReport r) {
            r.overtaking(overtaking).crossingJunction(crossingJunction).waitingAtJunction(waitingAtJunction).lane(lane)
                    .stage(stage).limitedBy(limitedBy).steeredBy(steeredBy);
        }
    }

    private int ticks;
    private double[] speed = new double[256];
    private double[] steering = new double[256];
    private int clamps;
    private int[] clampTick = new int[8];
    private double[] askedSpeed = new double[8];
    private double[] askedSteering = new double[8];
    private int requests;
    /** A request's tick; its junction is {@code j} for a claim and {@code -1 - j} for a release. */
    private int[] requestTick = new int[8];
    private int[] requestJunction = new int[8];
    private int reports;
    private int[] reportTick = new int[8];
    private Report[] report = new Report[8];
    private int failedAt = -1;
    /** The sensors its controller took ({@link sitcov.control.Sensor#bits}); what a program takes by default until told. */
    private int sensors = sitcov.control.Sensor.bits(sitcov.control.Sensor.reported());
    private ControllerFailure.Kind failureKind;
    private String failureMessage;

    /** Logs are equal when they hold the same commands: the same run, as far as the car is concerned. */
    @Override
    public boolean equals(Object o) {
        return o instanceof CommandLog l && ticks == l.ticks && clamps == l.clamps && requests == l.requests
                && reports == l.reports && failedAt == l.failedAt && failureKind == l.failureKind
                && java.util.Objects.equals(failureMessage, l.failureMessage)
                && Arrays.equals(speed, 0, ticks, l.speed, 0, ticks) && Arrays.equals(steering, 0, ticks, l.steering, 0, ticks)
                && Arrays.equals(clampTick, 0, clamps, l.clampTick, 0, clamps)
                && Arrays.equals(askedSpeed, 0, clamps, l.askedSpeed, 0, clamps)
                && Arrays.equals(askedSteering, 0, clamps, l.askedSteering, 0, clamps)
                && Arrays.equals(requestTick, 0, requests, l.requestTick, 0, requests)
                && Arrays.equals(requestJunction, 0, requests, l.requestJunction, 0, requests)
                && Arrays.equals(reportTick, 0, reports, l.reportTick, 0, reports)
                && Arrays.equals(report, 0, reports, l.report, 0, reports);
    }

    @Override
    public int hashCode() {
        int h = ticks;
        for (int t = 0; t < ticks; t++) {
            h = 31 * h + Double.hashCode(speed[t]) + 17 * Double.hashCode(steering[t]);
        }
        return h;
    }

    /** The ticks logged: each one a command, or the failure that ended the run. */
    /** The sensors the run's controller took: what a viewer draws of its observation. Not a command: equality ignores it. */
    public java.util.Set<sitcov.control.Sensor> sensors() {
        return sitcov.control.Sensor.of(sensors);
    }

    public void sensors(java.util.Set<sitcov.control.Sensor> taken) {
        sensors = sitcov.control.Sensor.bits(taken);
    }

    public int ticks() {
        return ticks;
    }

    /** Logs a tick's command as carried out: the speed (metres a tick) and steering (degrees) after clamping. */
    public void command(double appliedSpeed, double appliedSteering) {
        if (ticks == speed.length) {
            speed = Arrays.copyOf(speed, 2 * ticks);
            steering = Arrays.copyOf(steering, 2 * ticks);
        }
        speed[ticks] = appliedSpeed;
        steering[ticks] = appliedSteering;
        ticks++;
    }

    /** The world clamped the last command logged: it asked for this speed (NaN: none) and steering. */
    public void clamped(double speedAsked, double steeringAsked) {
        if (clamps == clampTick.length) {
            clampTick = Arrays.copyOf(clampTick, 2 * clamps);
            askedSpeed = Arrays.copyOf(askedSpeed, 2 * clamps);
            askedSteering = Arrays.copyOf(askedSteering, 2 * clamps);
        }
        clampTick[clamps] = ticks - 1;
        askedSpeed[clamps] = speedAsked;
        askedSteering[clamps] = steeringAsked;
        clamps++;
    }

    /** The next command logged (at tick {@link #ticks()}) lets go of {@code junction} first, in this order. */
    public void release(int junction) {
        request(-1 - junction);
    }

    /** The next command logged asks for {@code junction}, after its releases, in this order. */
    public void claim(int junction) {
        request(junction);
    }

    private void request(int coded) {
        if (requests == requestTick.length) {
            requestTick = Arrays.copyOf(requestTick, 2 * requests);
            requestJunction = Arrays.copyOf(requestJunction, 2 * requests);
        }
        requestTick[requests] = ticks;
        requestJunction[requests] = coded;
        requests++;
    }

    /** The next command logged comes with this self-report: kept only where it differs from the last. */
    public void report(sitcov.control.SelfReport said) {
        Report last = reports == 0 ? Report.NOTHING : report[reports - 1];
        if (!last.sameAs(said)) {
            report(ticks, Report.of(said));
        }
    }

    /** From tick {@code tick} on the controller says {@code said} (ticks in order). */
    public void report(int tick, Report said) {
        if (reports == reportTick.length) {
            reportTick = Arrays.copyOf(reportTick, 2 * reports);
            report = Arrays.copyOf(report, 2 * reports);
        }
        reportTick[reports] = tick;
        report[reports] = said;
        reports++;
    }

    /** The controller gave no command this tick: the run ends in its failure. */
    public void failed(ControllerFailure.Kind kind, String message) {
        failedAt = ticks;
        failureKind = kind;
        failureMessage = message;
        ticks++;
    }

    public double speed(int tick) {
        return speed[tick];
    }

    public double steering(int tick) {
        return steering[tick];
    }

    public int clamps() {
        return clamps;
    }

    public int clampTick(int i) {
        return clampTick[i];
    }

    public double askedSpeed(int i) {
        return askedSpeed[i];
    }

    public double askedSteering(int i) {
        return askedSteering[i];
    }

    public int requests() {
        return requests;
    }

    public int requestTick(int i) {
        return requestTick[i];
    }

    /** Whether request {@code i} asks for its junction (else it lets go of it). */
    public boolean isClaim(int i) {
        return requestJunction[i] >= 0;
    }

    public int requestJunction(int i) {
        return requestJunction[i] >= 0 ? requestJunction[i] : -1 - requestJunction[i];
    }

    public int reports() {
        return reports;
    }

    public int reportTick(int i) {
        return reportTick[i];
    }

    public Report report(int i) {
        return report[i];
    }

    /** The tick the controller failed at, or -1. */
    public int failedAt() {
        return failedAt;
    }

    public ControllerFailure.Kind failureKind() {
        return failureKind;
    }

    public String failureMessage() {
        return failureMessage;
    }
}
