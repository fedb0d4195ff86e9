package sitcov.report;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import sitcov.analysis.Comparison;
import sitcov.analysis.Discovery;
import sitcov.analysis.SituationFaults;
import sitcov.analysis.Summary;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.SeedPlan;
import sitcov.figures.StatsFigures;
import sitcov.results.OutputFile;
import sitcov.results.ResultsFolder;
import sitcov.results.StatsCsv;
import sitcov.verdict.VerdictText;

/**
 * The statistics of a comparison, written beside its tables: {@code stats.csv}, {@code verdict.txt},
 * {@code discovery.csv}, {@code cell-faults.csv} and {@code uniformity.csv}, and their figures.
 * Their randomness (bootstrap resamples, random deals of maps to cells) comes from the master
 * seed's analysis streams, so they are reproduced byte for byte with the results.
 */
final class AnalysisFiles {
    /** Random deals of maps to cells for the uniformity test: p-values down to 1/201. */
    static final int DEALS = 200;

    private AnalysisFiles() {
    }

    static void write(ExperimentConfig config, Summary summary, Path folder) throws IOException {
        Comparison comparison = Comparison.of(config, summary, SeedPlan.analysis(config.masterSeed(), "bootstrap"));
        SituationFaults situations = SituationFaults.of(summary.results(), summary.faults());
        List<SituationFaults.Uniformity> uniformity = situations.uniformity(DEALS,
                SeedPlan.analysis(config.masterSeed(), "cell-deals"));
        OutputFile.writeLines(folder.resolve(ResultsFolder.STATS), StatsCsv.rows(comparison));
        OutputFile.writeLines(folder.resolve(ResultsFolder.VERDICT), VerdictText.lines(comparison, uniformity,
                config.budget()));
        OutputFile.writeLines(folder.resolve(ResultsFolder.DISCOVERY), discovery(summary));
        OutputFile.writeLines(folder.resolve(ResultsFolder.CELL_FAULTS), cellFaults(situations));
        OutputFile.writeLines(folder.resolve(ResultsFolder.UNIFORMITY), uniformity(uniformity));
        StatsFigures.writeAll(summary, comparison, folder);
    }

    static List<String> discovery(Summary summary) {
        List<String> rows = new ArrayList<>();
        rows.add("driver,replication,fault,ticks_at_first_find,candidates_at_first_find,ticks_spent");
        for (ReplicationResult r : summary.results()) {
            for (DriverRun d : r.drivers()) {
                Discovery found = Discovery.of(d, summary.faults());
                for (int f = 0; f < summary.faults().size(); f++) {
                    boolean never = found.ticksAtFirst(f) == Discovery.NEVER;
                    rows.add(d.driver() + "," + r.replication() + "," + summary.faults().get(f).id() + ","
                            + (never ? "" : found.ticksAtFirst(f)) + "," + (never ? "" : found.candidatesAtFirst(f)) + ","
                            + found.ticksSpent());
                }
            }
        }
        return rows;
    }

    static List<String> cellFaults(SituationFaults situations) {
        List<String> rows = new ArrayList<>();
        StringBuilder header = new StringBuilder("cell,maps");
        situations.faults().forEach(f -> header.append(",found_fault_").append(f.id()));
        rows.add(header.toString());
        for (Map.Entry<Integer, Integer> e : situations.mapsOfCell().entrySet()) {
            StringBuilder row = new StringBuilder(e.getKey() + "," + e.getValue());
            for (int n : situations.foundIn(e.getKey())) {
                row.append(',').append(n);
            }
            rows.add(row.toString());
        }
        return rows;
    }

    static List<String> uniformity(List<SituationFaults.Uniformity> tests) {
        List<String> rows = new ArrayList<>();
        rows.add("fault,maps,found,explained_by_cell,explained_by_chance,p_permutation");
        for (SituationFaults.Uniformity u : tests) {
            rows.add(String.format(Locale.ROOT, "%d,%d,%d,%.6f,%.6f,%.6f", u.fault().id(), u.maps(), u.found(),
                    u.explained(), u.byChance(), u.p()));
        }
        return rows;
    }
}
