package sitcov.results;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import sitcov.analysis.Comparison;
import sitcov.analysis.FaultTest;
import sitcov.analysis.MeasureTest;
import sitcov.analysis.PairedDifference;

/**
 * {@code stats.csv}: one row per measure and pair of drivers (kind {@code measure}), then one per
 * fault and pair (kind {@code fault}), in one schema; empty where a column does not apply or was not
 * computed. Differences are the earlier driver minus the later (for a fault, of each replication's
 * share of maps finding it); {@code role} is primary, exploratory (in the Holm family) or untested;
 * {@code p_adjusted} is the p the finding rests on (Holm-adjusted over the family, or the primary's
 * own); the pooled Fisher test and odds ratio, the Mann-Whitney p and Â12 are descriptive.
 */
public final class StatsCsv {
    static final String HEADER = "kind,name,driver_a,driver_b,role,finding,note,replications,mean_a,mean_b,difference,"
            + "ci_low,ci_high,spread,differing,p,p_smallest,p_adjusted,detectable_80,margin,p_tost,p_tost_adjusted,"
            + "tost_low,tost_high,p_mann_whitney_unpaired,a12_unpaired,effect_unpaired,dispersion_a,dispersion_b,"
            + "found_a,maps_a,found_b,maps_b,p_fisher_pooled,odds_ratio_pooled,or_low,or_high";

    private StatsCsv() {
    }

    public static List<String> rows(Comparison comparison) {
        List<String> rows = new ArrayList<>();
        rows.add(HEADER);
        for (MeasureTest m : comparison.measures()) {
            String role = m.primary() ? "primary" : m.finding().tested() ? "exploratory" : "untested";
            rows.add(String.join(",", "measure", m.measure().key(), m.driverA(), m.driverB(), role, m.finding().key(),
                    text(m.note()), paired(m.paired()), num(m.margin()), num(m.pTost()), num(m.pTostAdjusted()),
                    num(m.tostLow()), num(m.tostHigh()), num(m.pMannWhitney()), num(m.a12()), m.effect().label(),
                    ",,,,,,,,,"));
        }
        for (FaultTest f : comparison.faults()) {
            String role = f.finding().tested() ? "exploratory" : "untested";
            rows.add(String.join(",", "fault", "fault_" + f.fault().id(), f.driverA(), f.driverB(), role, f.finding().key(),
                    text(f.note()), paired(f.paired()), ",,,,,,,", num(f.dispersionA()), num(f.dispersionB()),
                    Long.toString(f.foundA()), Long.toString(f.mapsA()), Long.toString(f.foundB()), Long.toString(f.mapsB()),
                    num(f.pFisher()), num(f.oddsRatio()), num(f.oddsLow()), num(f.oddsHigh())));
        }
        return rows;
    }

    private static String paired(PairedDifference d) {
        return String.join(",", Integer.toString(d.replications()), num(d.meanA()), num(d.meanB()),
                num(d.difference().estimate()), num(d.difference().low()), num(d.difference().high()), num(d.spread()),
                Integer.toString(d.differing()), num(d.p()), num(d.smallestP()), num(d.pAdjusted()), num(d.detectable()));
    }

    /** Six significant digits, empty for NaN: what was not computed stays visibly blank. */
    static String num(double v) {
        return Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.6g", v);
    }

    /** A note in one field: commas would split it. */
    private static String text(String note) {
        return note == null ? "" : note.replace(',', ';');
    }
}
