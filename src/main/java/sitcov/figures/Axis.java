package sitcov.figures;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * One axis from 0: the values labelled, ascending from 0, and where the panel ends ({@code end}, at
 * or a little beyond the last label, so that a mark at the last value sits inside the frame).
 */
record Axis(List<Double> ticks, double end) {
    /** Steps an axis may take, times a power of ten, largest first. */
    private static final double[] STEPS = {5, 2.5, 2, 1};
    /** How far an axis may run past the data's maximum: less than a quarter of it. */
    static final double MAX_OVERSHOOT = 1.25;
    /** Room beyond the last label of a padded axis, as a share of it. */
    private static final double PAD = 0.04;

    Axis {
        ticks = List.copyOf(ticks);
    }

    /** For values up to {@code max}: the largest round step (1, 2, 2.5, 5 times a power of ten) giving 4 to 8 steps. */
    static Axis upTo(double max) {
        return of(max, false);
    }

    /** For whole numbers (counts) up to {@code max}: as {@link #upTo}, but every label a whole number. */
    static Axis counts(double max) {
        return of(max, true);
    }

    /**
     * For whole numbers of at most {@code count} (the faults of the experiment): the axis ends at the
     * count itself, labelled; up to 10 every whole number, above that round whole steps.
     */
    static Axis toCount(int count) {
        if (count <= 10) {
            return steps(1, Math.max(1, count));
        }
        long step = wholeStep(count);
        List<Double> ticks = new ArrayList<>();
        for (long v = 0; v <= count; v += step) {
            ticks.add((double) v);
        }
        double last = ticks.get(ticks.size() - 1);
        if (last != count) {
            if (count - last < step / 2.0) {
                ticks.remove(ticks.size() - 1); // the count's label would run into this one
            }
            ticks.add((double) count);
        }
        return new Axis(ticks, count);
    }

    /** The least of 1, 2, 5, 10, 20, 50, ... that takes at most 10 steps to {@code count}. */
    private static long wholeStep(int count) {
        for (long p = 1; ; p *= 10) {
            for (long m : new long[] {1, 2, 5}) {
                if (count / (m * p) <= 10) {
                    return m * p;
                }
            }
        }
    }

    /** Labels at 0, step, ..., n × step; the axis ends at the last. */
    static Axis steps(double step, int n) {
        List<Double> ticks = new ArrayList<>();
        for (int i = 0; i <= n; i++) {
            ticks.add(i * step);
        }
        return new Axis(ticks, n * step);
    }

    private static Axis of(double max, boolean whole) {
        if (!(max > 0)) {
            return whole ? steps(1, 1) : steps(0.2, 5);
        }
        for (int e = (int) Math.floor(Math.log10(max)); ; e--) {
            for (double m : STEPS) {
                double step = m * Math.pow(10, e);
                if (whole && (step < 1 || Math.abs(step - Math.rint(step)) > 1e-9)) {
                    continue;
                }
                int n = (int) Math.ceil(max / step - 1e-9);
                // a step of at most max / 4 always passes, and the largest round one is above max / 8
                if (n >= 4 && n * step < MAX_OVERSHOOT * max) {
                    return steps(whole ? Math.rint(step) : step, n);
                }
            }
            if (whole && e <= 0) {
                return steps(1, (int) Math.ceil(max - 1e-9)); // 1, 2 or 3: a label per unit
            }
        }
    }

    /** A label as the axis writes it: every label with the decimals its step needs (0.5, 1.0, 1.5), none for whole steps. */
    String label(double v) {
        double step = ticks.size() > 1 ? ticks.get(1) - ticks.get(0) : 1;
        int decimals = 0;
        while (decimals < 6 && Math.abs(step * Math.pow(10, decimals) - Math.rint(step * Math.pow(10, decimals))) > 1e-6) {
            decimals++;
        }
        return String.format(Locale.ROOT, "%." + decimals + "f", v);
    }

    double last() {
        return ticks.get(ticks.size() - 1);
    }

    /** The same labels, the panel reaching a little beyond the last, so that a dot or line there is not on the frame. */
    Axis padded() {
        return new Axis(ticks, Math.max(end, last() * (1 + PAD)));
    }
}
