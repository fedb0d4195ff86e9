package sitcov.report;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import sitcov.analysis.Comparison;
import sitcov.analysis.ControllerFailures;
import sitcov.analysis.Discovery;
import sitcov.analysis.OwnFailures;
import sitcov.analysis.SituationFaults;
import sitcov.analysis.Summary;
import sitcov.analysis.VariantFindings;
import sitcov.experiment.DriverRun;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.ReplicationResult;
import sitcov.experiment.SeedPlan;
import sitcov.figures.StatsFigures;
import sitcov.results.Columns;
import sitcov.results.OutputFile;
import sitcov.results.ResultsFolder;
import sitcov.results.StatsCsv;
import sitcov.verdict.ControllerFailuresText;
import sitcov.verdict.OwnFailuresText;
import sitcov.verdict.VariantsText;
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
    static final Columns DISCOVERY = Columns.of("driver", "replication", "fault", "ticks_at_first_find",
            "candidates_at_first_find", "ticks_spent");
    static final Columns UNIFORMITY = Columns.of("fault", "maps", "found", "explained_by_cell", "explained_by_chance",
            "p_permutation");

    private AnalysisFiles() {
    }

    static void write(ExperimentConfig config, Summary summary, Path folder) throws IOException {
        Comparison comparison = Comparison.of(config, summary, SeedPlan.analysis(config.masterSeed(), "bootstrap"));
        SituationFaults situations = SituationFaults.of(summary.results(), summary.faults());
        List<SituationFaults.Uniformity> uniformity = situations.uniformity(DEALS,
                SeedPlan.analysis(config.masterSeed(), "cell-deals"));
        OutputFile.writeLines(folder.resolve(ResultsFolder.STATS), StatsCsv.rows(comparison));
        String reference = config.drivers().contains("random") ? "random" : config.drivers().get(0);
        OwnFailures own = OwnFailures.of(summary.results(), config.drivers(), reference,
                SeedPlan.analysis(config.masterSeed(), "own-failures"));
        List<String> verdict = new ArrayList<>(ControllerFailuresText.lines(
                ControllerFailures.of(summary.results(), config.variants())));
        verdict.addAll(VariantsText.lines(config, VariantFindings.of(summary.results(), config.variants())));
        verdict.addAll(VerdictText.lines(comparison, uniformity, config.budget()));
        if (!summary.results().isEmpty()) {
            verdict.addAll(OwnFailuresText.lines(own, reference, summary.results().size(),
                    config.onBuiltinFaults()));
        }
        OutputFile.writeLines(folder.resolve(ResultsFolder.VERDICT), verdict);
        OutputFile.writeLines(folder.resolve(ResultsFolder.OWN_FAILURES), ownFailures(own));
        OutputFile.writeLines(folder.resolve(ResultsFolder.DISCOVERY), discovery(summary));
        OutputFile.writeLines(folder.resolve(ResultsFolder.CELL_FAULTS), cellFaults(situations));
        OutputFile.writeLines(folder.resolve(ResultsFolder.UNIFORMITY), uniformity(uniformity));
        StatsFigures.writeAll(summary, comparison, folder);
    }

    static final Columns OWN_FAILURES = Columns.of("replication", "driver", "map_index", "map", "external_seed",
            "internal_seed", "cell", "accidents", "replay");

    /** The own failures, each with the command that replays it from inside the results folder. */
    static List<String> ownFailures(OwnFailures own) {
        List<String> rows = new ArrayList<>();
        rows.add(OWN_FAILURES.header());
        for (OwnFailures.Failure f : own.failures()) {
            rows.add(OWN_FAILURES.row().set("replication", f.replication()).set("driver", f.driver())
                    .set("map_index", f.mapIndex()).set("map", f.run().map().text())
                    .set("external_seed", f.run().externalSeed()).set("internal_seed", f.run().internalSeed())
                    .set("cell", f.run().cell())
                    .set("accidents", String.join("+", f.types().stream().map(Enum::name).toList()))
                    .set("replay", "java -jar \"$" + ReportFaultMaps.JAR + "\" replay . --replication " + f.replication()
                            + " --driver " + f.driver() + " --map " + f.mapIndex()).text());
        }
        return rows;
    }

    static List<String> discovery(Summary summary) {
        List<String> rows = new ArrayList<>();
        rows.add(DISCOVERY.header());
        for (ReplicationResult r : summary.results()) {
            for (DriverRun d : r.drivers()) {
                Discovery found = Discovery.of(d, summary.faults());
                for (int f = 0; f < summary.faults().size(); f++) {
                    boolean never = found.ticksAtFirst(f) == Discovery.NEVER;
                    rows.add(DISCOVERY.row().set("driver", d.driver()).set("replication", r.replication())
                            .set("fault", summary.faults().get(f).id())
                            .set("ticks_at_first_find", never ? "" : found.ticksAtFirst(f))
                            .set("candidates_at_first_find", never ? "" : found.candidatesAtFirst(f))
                            .set("ticks_spent", found.ticksSpent()).text());
                }
            }
        }
        return rows;
    }

    static List<String> cellFaults(SituationFaults situations) {
        List<String> rows = new ArrayList<>();
        List<String> names = new ArrayList<>(List.of("cell", "maps"));
        situations.faults().forEach(f -> names.add("found_fault_" + f.id()));
        Columns columns = new Columns(names);
        rows.add(columns.header());
        for (Map.Entry<Integer, Integer> e : situations.mapsOfCell().entrySet()) {
            Columns.Row row = columns.row().set("cell", e.getKey()).set("maps", e.getValue());
            int[] found = situations.foundIn(e.getKey());
            for (int f = 0; f < found.length; f++) {
                row.set(names.get(2 + f), found[f]);
            }
            rows.add(row.text());
        }
        return rows;
    }

    static List<String> uniformity(List<SituationFaults.Uniformity> tests) {
        List<String> rows = new ArrayList<>();
        rows.add(UNIFORMITY.header());
        for (SituationFaults.Uniformity u : tests) {
            rows.add(UNIFORMITY.row().set("fault", u.variant().id()).set("maps", u.maps()).set("found", u.found())
                    .set("explained_by_cell", sixPlaces(u.explained())).set("explained_by_chance", sixPlaces(u.byChance()))
                    .set("p_permutation", sixPlaces(u.p())).text());
        }
        return rows;
    }

    private static String sixPlaces(double v) {
        return String.format(Locale.ROOT, "%.6f", v);
    }
}
