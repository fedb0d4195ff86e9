package sitcov.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import sitcov.experiment.Comparison;

/**
 * {@code stats.csv}: one row per measure and pair of drivers (kind {@code measure}), then one per
 * fault and pair (kind {@code fault}); columns that do not apply to a kind are empty. Differences are
 * the earlier driver minus the later; an odds ratio above 1 favours the earlier driver.
 */
final class StatsCsv {
    static final String HEADER = "kind,name,driver_a,driver_b,replications,mean_a,mean_b,difference,ci_low,ci_high,"
            + "p_wilcoxon,p_mann_whitney,a12,effect,found_a,maps_a,found_b,maps_b,p_fisher,p_holm,odds_ratio,or_low,or_high";

    private StatsCsv() {
    }

    static List<String> rows(Comparison comparison) {
        List<String> rows = new ArrayList<>();
        rows.add(HEADER);
        for (Comparison.MeasureTest m : comparison.measures()) {
            rows.add(String.format(Locale.ROOT, "measure,%s,%s,%s,%d,%.6f,%.6f,%.6f,%.6f,%.6f,%.6g,%.6g,%.4f,%s,,,,,,,,,",
                    m.measure().key(), m.driverA(), m.driverB(), m.replications(), m.meanA(), m.meanB(),
                    m.difference().estimate(), m.difference().low(), m.difference().high(), m.pWilcoxon(),
                    m.pMannWhitney(), m.a12(), m.effect().label()));
        }
        for (Comparison.FaultTest f : comparison.faults()) {
            rows.add(String.format(Locale.ROOT, "fault,fault_%d,%s,%s,,,,,,,,,,,%d,%d,%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g",
                    f.fault().id(), f.driverA(), f.driverB(), f.foundA(), f.mapsA(), f.foundB(), f.mapsB(), f.p(),
                    f.pHolm(), f.oddsRatio(), f.oddsLow(), f.oddsHigh()));
        }
        return rows;
    }
}
