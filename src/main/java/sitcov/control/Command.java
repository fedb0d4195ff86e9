package sitcov.control;

import java.util.Arrays;

/**
 * What a controller asks of the car in one tick: a speed change (metres a tick, per tick) — or,
 * where it wants a speed to the bit, that speed itself — and a steering angle (degrees, positive
 * turning towards larger bearings), which the world clamps to the
 * car's limits (0 to 2.5 m a tick, 15° a tick) and records when it had to; junctions to let go of
 * and to ask for (let go first, then asked for, in order); and an optional self-report that the
 * world keeps as information only and never judges by. One object is reused tick after tick.
 */
public final class Command {
    private double speedChange;
    private double speed = Double.NaN;
    private double steering;
    private int[] releases = new int[4];
    private int releaseCount;
    private int[] claims = new int[4];
    private int claimCount;
    private SelfReport report = new SelfReport();

    /** Clears everything: no speed change, straight on, no requests, nothing reported. */
    public void clear() {
        speedChange = 0;
        speed = Double.NaN;
        steering = 0;
        releaseCount = 0;
        claimCount = 0;
        report.clear();
    }

    public Command speedChange(double metresPerTick) {
        this.speedChange = metresPerTick;
        return this;
    }

    /**
     * Asks for a speed outright (metres a tick) instead of a change: current + (wanted − current) is
     * not always wanted in double arithmetic, and a controller replayed elsewhere must move the car
     * to the bit. The world clamps it as it clamps a change.
     */
    public Command speed(double metresPerTick) {
        this.speed = metresPerTick;
        return this;
    }

    /** The speed asked for outright, or NaN when the command gives a change instead. */
    public double speed() {
        return speed;
    }

    public Command steering(double degrees) {
        this.steering = degrees;
        return this;
    }

    /** Asks for junction {@code junction}; the world grants it when {@link RightOfWay#wouldGrant} said so. */
    public Command claim(int junction) {
        if (claimCount == claims.length) {
            claims = Arrays.copyOf(claims, 2 * claimCount);
        }
        claims[claimCount++] = junction;
        return this;
    }

    /** Lets go of junction {@code junction} (nothing happens when the car does not hold it). */
    public Command release(int junction) {
        if (releaseCount == releases.length) {
            releases = Arrays.copyOf(releases, 2 * releaseCount);
        }
        releases[releaseCount++] = junction;
        return this;
    }

    public double speedChange() {
        return speedChange;
    }

    public double steering() {
        return steering;
    }

    public int claimCount() {
        return claimCount;
    }

    public int claimAt(int index) {
        return claims[index];
    }

    public int releaseCount() {
        return releaseCount;
    }

    public int releaseAt(int index) {
        return releases[index];
    }

    public SelfReport report() {
        return report;
    }
}
