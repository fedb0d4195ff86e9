package sitcov.results;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import sitcov.analysis.CurvePoint;
import sitcov.analysis.Metrics;
import sitcov.analysis.Summary;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ReplicationResult;
import sitcov.judge.Variant;
import sitcov.judge.Notion;

/**
 * The tables of a comparison, from its {@link Summary}: {@code summary.csv} (the paper's measures
 * per driver, replication and detection notion), {@code table2.csv} (the paper's Table 2 for every
 * pair of drivers) and {@code coverage-curve.csv}.
 */
public final class ResultsTables {
    /** coverage-curve.csv: a point each time a driver's covered cells grew. */
    public static final Columns CURVE =
            Columns.of("driver", "replication", "candidates", "maps_run", "ticks", "cells_covered");

    private final ExperimentConfig config;
    private final Summary summary;

    public ResultsTables(ExperimentConfig config, Summary summary) {
        this.config = config;
        this.summary = summary;
    }

    /** summary.csv's columns: one {@code fault_ID} column per seeded fault, in id order. */
    public Columns summaryColumns() {
        List<String> names = new ArrayList<>(List.of("driver", "replication", "notion", "maps_run", "cells_covered",
                "cells_total", "cells_seen", "method_prop_fault", "prop_map_all_fault", "avg_map_fault"));
        summary.faults().forEach(f -> names.add(faultColumn(f)));
        return new Columns(names);
    }

    private static String faultColumn(Variant f) {
        return "fault_" + f.id();
    }

    public List<String> summary() {
        Columns columns = summaryColumns();
        List<String> rows = new ArrayList<>();
        rows.add(columns.header());
        int seen = summary.cellsSeen();
        for (ReplicationResult r : summary.results()) {
            for (DriverRun d : r.drivers()) {
                for (Notion notion : Notion.values()) {
                    Metrics x = summary.metrics(r.replication(), d.driver(), notion);
                    Columns.Row row = columns.row().set("driver", d.driver()).set("replication", r.replication())
                            .set("notion", notion.key()).set("maps_run", x.maps()).set("cells_covered", x.cells())
                            .set("cells_total", config.grid().cells()).set("cells_seen", seen)
                            .set("method_prop_fault", share(x.methodPropFault()))
                            .set("prop_map_all_fault", share(x.propMapAllFault()))
                            .set("avg_map_fault", share(x.avgMapFault()));
                    double[] perFault = x.perFault();
                    for (int f = 0; f < perFault.length; f++) {
                        row.set(faultColumn(summary.faults().get(f)), share(perFault[f]));
                    }
                    rows.add(row.text());
                }
            }
        }
        return rows;
    }

    private static String share(double v) {
        return String.format(Locale.ROOT, "%.4f", v);
    }

    /**
     * The paper's Table 2: per fault and notion, the share of maps finding it by each driver (mean
     * over replications), then the difference for every pair of drivers (earlier minus later).
     */
    public List<String> table2() {
        List<String> drivers = summary.drivers();
        List<String> names = new ArrayList<>(List.of("fault", "name", "notion"));
        names.addAll(drivers);
        for (int i = 0; i < drivers.size(); i++) {
            for (int j = i + 1; j < drivers.size(); j++) {
                names.add(difference(drivers.get(i), drivers.get(j)));
            }
        }
        Columns columns = new Columns(names);
        List<String> rows = new ArrayList<>();
        rows.add(columns.header());
        List<Variant> faults = summary.faults();
        for (Notion notion : Notion.values()) {
            double[][] mean = new double[drivers.size()][];
            for (int d = 0; d < drivers.size(); d++) {
                mean[d] = summary.mean(drivers.get(d), notion).perFault();
            }
            for (int f = 0; f < faults.size(); f++) {
                Columns.Row row = columns.row().set("fault", faults.get(f).id()).set("name", faults.get(f).label())
                        .set("notion", notion.key());
                for (int d = 0; d < drivers.size(); d++) {
                    row.set(drivers.get(d), share(mean[d][f]));
                }
                for (int i = 0; i < drivers.size(); i++) {
                    for (int j = i + 1; j < drivers.size(); j++) {
                        row.set(difference(drivers.get(i), drivers.get(j)), share(mean[i][f] - mean[j][f]));
                    }
                }
                rows.add(row.text());
            }
        }
        return rows;
    }

    private static String difference(String earlier, String later) {
        return earlier + "_minus_" + later;
    }

    public List<String> curve() {
        List<String> rows = new ArrayList<>();
        rows.add(CURVE.header());
        for (ReplicationResult r : summary.results()) {
            for (DriverRun d : r.drivers()) {
                for (CurvePoint p : CurvePoint.of(r.replication(), d)) {
                    rows.add(CURVE.row().set("driver", p.driver()).set("replication", p.replication())
                            .set("candidates", p.candidates()).set("maps_run", p.mapsRun()).set("ticks", p.ticks())
                            .set("cells_covered", p.cellsCovered()).text());
                }
            }
        }
        return rows;
    }
}
