package sitcov.control;

/** The speed change that takes a car from one speed to another exactly, as the world adds it. */
public final class SpeedChange {
    private SpeedChange() {
    }

    /**
     * A change {@code d} with {@code from + d == to} in double arithmetic. The plain difference
     * usually is one; where rounding makes it miss by an ulp, the neighbouring doubles are tried,
     * so a controller that wants a speed gets exactly that speed.
     */
    public static double between(double from, double to) {
        double d = to - from;
        for (int step = 0; step < 8 && from + d != to; step++) {
            d = from + d < to ? Math.nextUp(d) : Math.nextDown(d);
        }
        return d;
    }
}
