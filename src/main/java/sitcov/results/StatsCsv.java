package sitcov.results;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import sitcov.analysis.Comparison;
import sitcov.analysis.FaultComparison;
import sitcov.analysis.MeasureComparison;
import sitcov.analysis.PairedDifference;

/**
 * {@code stats.csv}: one row per measure and pair of drivers (kind {@code measure}), then one per
 * fault and pair (kind {@code fault}), in one schema; empty where a column does not apply or was not
 * computed. Differences are the earlier driver minus the later (for a fault, of each replication's
 * share of maps finding it); {@code role} is primary, exploratory (in a family) or untested;
 * {@code p_adjusted} is the p the finding rests on and {@code adjustment} how it was adjusted: none (the
 * primary's own), closed-holm (the measures' family) or bh (the faults' screening, a q-value);
 * {@code higher_a}, {@code higher_b} and {@code superiority_paired} (their share, ties counted half)
 * are the paired effect size; the pooled Fisher test and odds ratio, the Mann-Whitney p and Â12
 * (unpaired) are descriptive.
 */
public final class StatsCsv {
    static final Columns COLUMNS = Columns.of("kind", "name", "driver_a", "driver_b", "role", "finding", "note",
            "replications", "mean_a", "mean_b", "difference", "ci_low", "ci_high", "spread", "differing", "higher_a", "higher_b",
            "superiority_paired", "p", "p_smallest", "p_adjusted", "adjustment", "detectable_80", "margin", "p_tost", "p_tost_adjusted", "tost_low", "tost_high",
            "p_mann_whitney_unpaired", "a12_unpaired", "effect_unpaired", "dispersion_a", "dispersion_b", "found_a",
            "maps_a", "found_b", "maps_b", "p_fisher_pooled", "odds_ratio_pooled", "or_low", "or_high");
    static final String HEADER = COLUMNS.header();

    private StatsCsv() {
    }

    /** The table's lines, header first; a measure's row leaves the fault columns blank, and a fault's the measure's. */
    public static List<String> rows(Comparison comparison) {
        List<String> rows = new ArrayList<>();
        rows.add(HEADER);
        for (MeasureComparison m : comparison.measures()) {
            String role = m.primary() ? "primary" : m.finding().tested() ? "exploratory" : "untested";
            Columns.Row row = COLUMNS.row().set("kind", "measure").set("name", m.measure().key())
                    .set("driver_a", m.driverA()).set("driver_b", m.driverB()).set("role", role)
                    .set("finding", m.finding().key()).set("note", text(m.note()));
            paired(row, m.paired(), m.primary() ? "none" : role.equals("exploratory") ? "closed-holm" : "");
            row.set("margin", num(m.margin())).set("p_tost", num(m.pTost())).set("p_tost_adjusted", num(m.pTostAdjusted()))
                    .set("tost_low", num(m.tostLow())).set("tost_high", num(m.tostHigh()))
                    .set("p_mann_whitney_unpaired", num(m.pMannWhitney())).set("a12_unpaired", num(m.a12()))
                    .set("effect_unpaired", m.effect().label());
            rows.add(row.blankRest().text());
        }
        for (FaultComparison f : comparison.faults()) {
            String role = f.finding().tested() ? "exploratory" : "untested";
            Columns.Row row = COLUMNS.row().set("kind", "fault").set("name", "fault_" + f.variant().id())
                    .set("driver_a", f.driverA()).set("driver_b", f.driverB()).set("role", role)
                    .set("finding", f.finding().key()).set("note", text(f.note()));
            paired(row, f.paired(), role.equals("exploratory") ? "bh" : "");
            row.set("dispersion_a", num(f.dispersionA())).set("dispersion_b", num(f.dispersionB()))
                    .set("found_a", f.foundA()).set("maps_a", f.mapsA()).set("found_b", f.foundB()).set("maps_b", f.mapsB())
                    .set("p_fisher_pooled", num(f.pFisher())).set("odds_ratio_pooled", num(f.oddsRatio()))
                    .set("or_low", num(f.oddsLow())).set("or_high", num(f.oddsHigh()));
            rows.add(row.blankRest().text());
        }
        return rows;
    }

    private static void paired(Columns.Row row, PairedDifference d, String adjustment) {
        row.set("replications", d.replications()).set("mean_a", num(d.meanA())).set("mean_b", num(d.meanB()))
                .set("difference", num(d.difference().estimate())).set("ci_low", num(d.difference().low()))
                .set("ci_high", num(d.difference().high())).set("spread", num(d.spread())).set("differing", d.differing())
                .set("higher_a", d.higherA()).set("higher_b", d.higherB()).set("superiority_paired", num(d.superiority()))
                .set("p", num(d.p())).set("p_smallest", num(d.smallestP())).set("p_adjusted", num(d.pAdjusted()))
                .set("adjustment", adjustment)
                .set("detectable_80", num(d.detectable()));
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
