package sitcov.seam;

import java.util.random.RandomGenerator;
import sitcov.geom.Bearing;

/**
 * The car's own pose is reported with noise: its x and y each off by a normal draw of the fault's
 * standard deviation in metres, its heading by one in degrees, drawn anew each tick. Its speed is true.
 */
final class PoseNoise extends ObservationView {
    private RandomGenerator draws;
    private double metres;
    private double degrees;
    private double dx;
    private double dy;
    private double dh;

    PoseNoise(RandomGenerator draws, double metres, double degrees) {
        this.draws = draws;
        this.metres = metres;
        this.degrees = degrees;
    }

    @Override
    void started() {
        dx = metres * normal();
        dy = metres * normal();
        dh = degrees * normal();
    }

    /** A standard normal draw by Box–Muller from two uniform draws: the same numbers on every JDK. */
    private double normal() {
        double u = draws.nextDouble();
        double v = draws.nextDouble();
        return Math.sqrt(-2 * Math.log1p(-u)) * Math.cos(2 * Math.PI * v);
    }

    @Override
    int parts() {
        return Part.POSE;
    }

    @Override
    public double x() {
        return real.x() + dx;
    }

    @Override
    public double y() {
        return real.y() + dy;
    }

    @Override
    public double heading() {
        return Bearing.normalise(real.heading() + dh);
    }
}
