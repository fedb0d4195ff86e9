package sitcov.drivers;

import sitcov.oracle.AccidentType;
import sitcov.oracle.Margins;

/**
 * How near the reference car came to failing in one run, as one number for a search to minimise:
 * the least robustness ρ over the accident types, each in units of its typical margin, so that a
 * centre-line margin of a few centimetres counts as much as a gap of a metre to a moving car. The
 * units are the median margins of the fault-free car on 3000 random maps (master seed 2026): 1 m
 * to a parked car, 1 m to a moving car, 0.2 m to the road's edge, 0.05 m to the centre line, 4700
 * ticks left when the Target is reached. Negative exactly when the run had an accident.
 */
public final class Stress {
    private static final double[] UNIT = {1.0, 1.0, 0.2, 0.05, 4700};
    /** Stress at which a search stops telling failures apart: every failure is as good as any other. */
    public static final double FAILED = -1;

    private Stress() {
    }

    /** The least normalised ρ of {@code margins}; infinite when none is known. */
    public static double of(Margins margins) {
        double least = Double.POSITIVE_INFINITY;
        for (AccidentType t : AccidentType.values()) {
            least = Math.min(least, of(margins, t));
        }
        return least;
    }

    /** The normalised ρ of one accident type's requirement, for a search after that requirement alone; infinite when not known. */
    public static double of(Margins margins, AccidentType type) {
        double rho = margins.robustness(type);
        return Double.isNaN(rho) ? Double.POSITIVE_INFINITY : rho / UNIT[type.ordinal()];
    }
}
