package sitcov.report;

import java.util.Locale;
import sitcov.verdict.VerdictText;

/** The numbers of a CSV file written for people: counts whole, shares in per cent, p-values short, a dash for none. */
final class HtmlNumbers {
    static final String NONE = "—";

    private HtmlNumbers() {
    }

    /** A count or mean: whole numbers without decimals, others to three significant places or so. */
    static String number(String csv) {
        if (csv.isEmpty()) {
            return NONE;
        }
        double v = Double.parseDouble(csv);
        return number(v);
    }

    static String number(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return String.format(Locale.ROOT, "%d", (long) v);
        }
        return VerdictText.number(v);
    }

    /** A mean or estimate, with the same places whether or not it happens to be whole: "35.00", "34.50", "169.6". */
    static String mean(String csv) {
        return csv.isEmpty() ? NONE : VerdictText.number(Double.parseDouble(csv));
    }

    /** A signed difference: "+9.17", "−0.067". */
    static String signed(String csv) {
        if (csv.isEmpty()) {
            return NONE;
        }
        return VerdictText.signed(Double.parseDouble(csv));
    }

    /** A share 0..1 in per cent: "91.8 %", with more places below 1 % so that small shares do not read as 0. */
    static String percent(String csv) {
        if (csv.isEmpty()) {
            return NONE;
        }
        return percent(Double.parseDouble(csv));
    }

    static String percent(double share) {
        double pc = 100 * share;
        if (pc == 0) {
            return "0 %";
        }
        return String.format(Locale.ROOT, Math.abs(pc) < 1 ? "%.2f %%" : "%.1f %%", pc);
    }

    /** A difference of shares in percentage points: "+3.7". */
    static String points(String csv) {
        if (csv.isEmpty()) {
            return NONE;
        }
        double pts = 100 * Double.parseDouble(csv);
        if (pts == 0) {
            return "0";
        }
        return String.format(Locale.ROOT, Math.abs(pts) < 1 && pts != 0 ? "%+.2f" : "%+.1f", pts);
    }

    static String p(String csv) {
        return csv.isEmpty() ? NONE : VerdictText.p(Double.parseDouble(csv));
    }
}
