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
import sitcov.faults.Fault;

/**
 * The tables of a comparison, from its {@link Summary}: {@code summary.csv} (the paper's measures
 * per driver, replication and detection notion), {@code table2.csv} (the paper's Table 2 for every
 * pair of drivers) and {@code coverage-curve.csv}.
 */
public final class ResultsTables {
    private static final List<String> NOTIONS = List.of("differential", "paper");

    private final ExperimentConfig config;
    private final Summary summary;

    public ResultsTables(ExperimentConfig config, Summary summary) {
        this.config = config;
        this.summary = summary;
    }

    public List<String> summary() {
        List<String> rows = new ArrayList<>();
        StringBuilder header = new StringBuilder("driver,replication,notion,maps_run,cells_covered,cells_total,cells_seen,"
                + "method_prop_fault,prop_map_all_fault,avg_map_fault");
        for (Fault f : summary.faults()) {
            header.append(",fault_").append(f.id());
        }
        rows.add(header.toString());
        int seen = summary.cellsSeen();
        for (ReplicationResult r : summary.results()) {
            for (DriverRun d : r.drivers()) {
                for (String notion : NOTIONS) {
                    Metrics x = summary.metrics(r.replication(), d.driver(), notion.equals("paper"));
                    StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "%s,%d,%s,%d,%d,%d,%d,%.4f,%.4f,%.4f",
                            d.driver(), r.replication(), notion, x.maps(), x.cells(), config.grid().cells(), seen,
                            x.methodPropFault(), x.propMapAllFault(), x.avgMapFault()));
                    for (double p : x.perFault()) {
                        s.append(String.format(Locale.ROOT, ",%.4f", p));
                    }
                    rows.add(s.toString());
                }
            }
        }
        return rows;
    }

    /**
     * The paper's Table 2: per fault and notion, the share of maps finding it by each driver (mean
     * over replications), then the difference for every pair of drivers (earlier minus later).
     */
    public List<String> table2() {
        List<String> drivers = summary.drivers();
        StringBuilder header = new StringBuilder("fault,name,notion");
        for (String d : drivers) {
            header.append(',').append(d);
        }
        for (int i = 0; i < drivers.size(); i++) {
            for (int j = i + 1; j < drivers.size(); j++) {
                header.append(',').append(drivers.get(i)).append("_minus_").append(drivers.get(j));
            }
        }
        List<String> rows = new ArrayList<>();
        rows.add(header.toString());
        List<Fault> faults = summary.faults();
        for (String notion : NOTIONS) {
            double[][] mean = new double[drivers.size()][];
            for (int d = 0; d < drivers.size(); d++) {
                mean[d] = summary.mean(drivers.get(d), notion.equals("paper")).perFault();
            }
            for (int f = 0; f < faults.size(); f++) {
                StringBuilder s = new StringBuilder(faults.get(f).id() + "," + faults.get(f).label() + "," + notion);
                for (double[] m : mean) {
                    s.append(String.format(Locale.ROOT, ",%.4f", m[f]));
                }
                for (int i = 0; i < drivers.size(); i++) {
                    for (int j = i + 1; j < drivers.size(); j++) {
                        s.append(String.format(Locale.ROOT, ",%.4f", mean[i][f] - mean[j][f]));
                    }
                }
                rows.add(s.toString());
            }
        }
        return rows;
    }

    public List<String> curve() {
        List<String> rows = new ArrayList<>();
        rows.add("driver,replication,candidates,maps_run,ticks,cells_covered");
        for (ReplicationResult r : summary.results()) {
            for (DriverRun d : r.drivers()) {
                for (CurvePoint p : CurvePoint.of(r.replication(), d)) {
                    rows.add(p.driver() + "," + p.replication() + "," + p.candidates() + "," + p.mapsRun() + "," + p.ticks()
                            + "," + p.cellsCovered());
                }
            }
        }
        return rows;
    }
}
