package sitcov.render;

import java.util.Locale;
import sitcov.oracle.AccidentType;
import sitcov.oracle.NearMiss;

/**
 * Near misses and robustness in words, the same wherever a user meets them (simulate's summary,
 * the pictures, the viewer): what each measure is, in its unit (metres or ticks); infinite is
 * "never" (never met: no parked car, never closing), NaN "unknown".
 */
public final class NearMissText {
    private NearMissText() {
    }

    /** What the measure is, in a few words. */
    public static String name(NearMiss m) {
        return switch (m) {
            case MOVING_GAP -> "gap to a moving car";
            case PARKED_GAP -> "gap to a parked car";
            case ROAD_EDGE -> "margin to the road's edge";
            case CENTRE_LINE -> "margin to the centre line";
            case TIME_TO_COLLISION -> "time to collision";
            case POST_ENCROACHMENT -> "post-encroachment time";
        };
    }

    /** A short name, for a picture's label or the viewer's header. */
    public static String shortName(NearMiss m) {
        return switch (m) {
            case MOVING_GAP -> "moving car";
            case PARKED_GAP -> "parked car";
            case ROAD_EDGE -> "road edge";
            case CENTRE_LINE -> "centre line";
            case TIME_TO_COLLISION -> "TTC";
            case POST_ENCROACHMENT -> "PET";
        };
    }

    /** Metres for the gaps and margins, ticks for the two times. */
    public static String unit(NearMiss m) {
        return switch (m) {
            case MOVING_GAP, PARKED_GAP, ROAD_EDGE, CENTRE_LINE -> "m";
            case TIME_TO_COLLISION, POST_ENCROACHMENT -> "ticks";
        };
    }

    /** The accident a measure below zero would be, or null for the two times. */
    public static AccidentType accident(NearMiss m) {
        return switch (m) {
            case MOVING_GAP -> AccidentType.CLASHWITHOTHERCAR;
            case PARKED_GAP -> AccidentType.CLASHWITHOBSTACLE;
            case ROAD_EDGE -> AccidentType.LEAVEROAD;
            case CENTRE_LINE -> AccidentType.CROSSCENTRELINE;
            case TIME_TO_COLLISION, POST_ENCROACHMENT -> null;
        };
    }

    /** ρ's unit: ticks for TIMEOUT, metres for the others. */
    public static String unit(AccidentType t) {
        return t == AccidentType.TIMEOUT ? "ticks" : "m";
    }

    /** {@code v} with {@code decimals} decimals and its unit; "never" when infinite, "unknown" when NaN. */
    public static String value(double v, String unit, int decimals) {
        if (Double.isNaN(v)) {
            return "unknown";
        }
        if (v == Double.POSITIVE_INFINITY) {
            return "never";
        }
        if (v == Double.NEGATIVE_INFINITY) {
            return "-inf " + unit;
        }
        String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
        if (s.matches("-0\\.?0*")) { // a tiny negative shown as zero is zero
            s = s.substring(1);
        }
        return s + " " + unit;
    }

    /** Whole ticks need no decimals: post-encroachment counts them. */
    public static String value(NearMiss m, double v, int decimals) {
        return value(v, unit(m), m == NearMiss.POST_ENCROACHMENT ? 0 : decimals);
    }

    /** Whole ticks need no decimals: TIMEOUT's ρ counts them. */
    public static String rho(AccidentType t, double v, int decimals) {
        return value(v, unit(t), t == AccidentType.TIMEOUT ? 0 : decimals);
    }
}
