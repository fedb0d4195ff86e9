package sitcov.oracle;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * How close one run came to each accident, as results keep it: the least value of every
 * {@link NearMiss} measure and the robustness ρ of every accident type's requirement (see
 * {@link NearMisses}). Values are kept to {@link #DECIMALS} decimals, so what a search sees of a run
 * is exactly what runs.csv gives back to a resumed one. Infinite: never met (no parked car, never
 * closing); NaN: not known (a run stopped at its verdict has no timeout margin; a results folder
 * written before margins were kept has none).
 */
public record Margins(List<Double> nearMisses, List<Double> robustness) {
    /** Decimals kept: a tenth of a millimetre, a ten-thousandth of a tick. */
    public static final int DECIMALS = 4;
    /** Beyond this a margin is as good as never met (a time to collision of 30 years). */
    private static final double NEVER = 1e9;
    private static final double SCALE = 1e4;

    /** Nothing known, for a run whose margins were not measured. */
    public static final Margins UNKNOWN = new Margins(
            Collections.nCopies(NearMiss.values().length, Double.NaN),
            Collections.nCopies(AccidentType.values().length, Double.NaN));

    public Margins {
        nearMisses = List.copyOf(nearMisses);
        robustness = List.copyOf(robustness);
        if (nearMisses.size() != NearMiss.values().length || robustness.size() != AccidentType.values().length) {
            throw new IllegalArgumentException("margins hold one value per near-miss measure and per accident type");
        }
    }

    /** What the watcher saw of a whole run, kept to {@link #DECIMALS} decimals. */
    public static Margins of(NearMisses watched) {
        List<Double> near = new ArrayList<>();
        for (NearMiss m : NearMiss.values()) {
            near.add(kept(watched.least(m)));
        }
        List<Double> rho = new ArrayList<>();
        for (AccidentType t : AccidentType.values()) {
            rho.add(kept(watched.robustness(t)));
        }
        return new Margins(near, rho);
    }

    /** {@code value} as results keep it: rounded to {@link #DECIMALS} decimals, huge values infinite. */
    public static double kept(double value) {
        if (Double.isNaN(value)) {
            return value;
        }
        if (value >= NEVER) {
            return Double.POSITIVE_INFINITY;
        }
        if (value <= -NEVER) {
            return Double.NEGATIVE_INFINITY;
        }
        return Math.rint(value * SCALE) / SCALE;
    }

    public double least(NearMiss measure) {
        return nearMisses.get(measure.ordinal());
    }

    /** ρ of the requirement that no accident of {@code type} happens: negative where one did. */
    public double robustness(AccidentType type) {
        return robustness.get(type.ordinal());
    }

    public boolean known() {
        return !robustness.stream().allMatch(v -> Double.isNaN(v));
    }
}
