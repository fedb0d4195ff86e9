package sitcov.report;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.judge.Variant;
import sitcov.judge.Notion;
import sitcov.recording.Recording;
import sitcov.results.ResultsFolder;

/**
 * For each fault, the first maps that found it, each with its row of runs.csv and a replay command
 * that runs as printed from this folder, and the pictures the report drew of them ({@link ReportPictures}).
 */
final class ReportFaultMaps {
    /** Maps listed per fault; the rest are in runs.csv. */
    static final int MAPS_PER_FAULT = 10;
    /** The shell variable the printed commands take sitcov's jar from. */
    static final String JAR = "SITCOV_JAR";

    private ReportFaultMaps() {
    }

    /** The command replaying row {@code row} of runs.csv from the results folder, into a picture of its own. */
    static String replay(int row) {
        return "java -jar \"$" + JAR + "\" replay . --row " + row + " --png replay-row-" + row + ".png";
    }

    /**
     * The command that runs row {@code row}'s faulty run again with the folder's controller, when that is
     * not the builtin car (which {@code replay} runs): {@code simulate} with the map, seeds, fault and controller.
     */
    /** The command that runs the row's map with its variant: a seeded fault in the reference, or the variant's controller. */
    static String rerun(int row, MapRun run, Variant variant, String controller) {
        String map = run.map() instanceof MapId.Situation s
                ? "--load " + ResultsFolder.SITUATIONS + "/" + s.name() + ".situation" : "--seed " + run.externalSeed();
        String with = variant instanceof Variant.Seeded ? " --faults " + variant.id() + " --controller \"" + controller + "\""
                : " --controller \"" + variant.spec() + "\"";
        return "java -jar \"$" + JAR + "\" simulate " + map + " --internal-seed " + run.internalSeed() + with
                + " --png run-row-" + row + ".png";
    }

    /** Whether the folder keeps the recordings that replay the row of variant {@code variant} on {@code run}'s map. */
    static boolean recorded(Path folder, MapRun run, int variant) {
        Path dir = folder.resolve(ResultsFolder.RECORDINGS);
        return Files.isRegularFile(dir.resolve(new Recording.RunKey(run.replication(), run.driver(), run.mapIndex(),
                variant).fileName())) && Files.isRegularFile(dir.resolve(new Recording.RunKey(run.replication(),
                run.driver(), run.mapIndex(), Recording.RunKey.REFERENCE).fileName()));
    }

    static void append(StringBuilder h, Path folder, ExperimentConfig config, List<MapRun> inOrder, String version,
                       ReportPictures pictures) {
        boolean builtin = config.controller().equals(ExperimentConfig.BUILTIN);
        boolean replayed = !builtin && inOrder.stream().anyMatch(run -> recorded(folder, run, Recording.RunKey.REFERENCE));
        h.append("<h2 id=\"found\">Maps that found each fault</h2><p class=\"muted\">Counts are of maps judged: every map each driver"
                + " ran in each replication (runs.csv). Each command replays its row side by side, the run without the"
                + " fault and the run with it, into a picture next to this page (add <code>--gif FILE</code> to watch"
                + " them). Run it in a shell opened in this folder, once ").append(JAR).append(" names sitcov's jar: in"
                + " the sitcov checkout, ").append(HtmlReport.command("mvn -q package -DskipTests && export " + JAR
                + "=$PWD/target/sitcov-" + version + ".jar")).append(builtin ? "" : replayed ? " This folder tested the"
                + " controller " + HtmlReport.esc(config.controller()) + ": each command replays the row from the commands"
                + " its runs carried out, kept in " + ResultsFolder.RECORDINGS + "/, so the controller need not be at hand."
                : " This folder tested the controller " + HtmlReport.esc(config.controller()) + ", not the builtin car that"
                + " replay runs: each command runs the map with the fault through that controller into a picture instead.")
                .append("</p><p class=\"muted\">").append(pictures.rule(builtin)).append("</p>");
        var faults = config.variants();
        int perMap = 1 + faults.size();
        for (int f = 0; f < faults.size(); f++) {
            List<String> found = new ArrayList<>();
            int total = 0;
            for (int m = 0; m < inOrder.size(); m++) {
                MapRun run = inOrder.get(m);
                var outcome = run.faults().get(f);
                if (outcome.found(Notion.DIFFERENTIAL)) {
                    total++;
                    if (found.size() < MAPS_PER_FAULT) {
                        int row = m * perMap + f + 2;
                        found.add(String.format(Locale.ROOT, "<li>replication %d, %s, map %d (%s): %s, row %d of runs.csv"
                                + "<br>%s</li>", run.replication(), HtmlReport.esc(run.driver()), run.mapIndex(),
                                HtmlReport.esc(run.map().text()), outcome.newAccident().map(Enum::name).orElse("FOUND"), row,
                                HtmlReport.command(builtin || recorded(folder, run, faults.get(f).id()) ? replay(row)
                                        : rerun(row, run, faults.get(f), config.controller()))));
                    }
                }
            }
            h.append(faults.get(f) instanceof Variant.Seeded ? "<h3>fault " : "<h3>variant ").append(faults.get(f).id()).append(" · ").append(HtmlReport.esc(faults.get(f).label()))
                    .append("</h3><p>found on ").append(total).append(" of the ").append(inOrder.size())
                    .append(" maps judged").append(total > found.size() ? " (the first " + found.size() + " listed)" : "")
                    .append("</p>");
            if (!found.isEmpty()) {
                h.append("<ul class=\"maps\">").append(String.join("", found)).append("</ul>");
            }
            Variant variant = faults.get(f);
            ReportPictures.append(h, folder, pictures.of(Optional.of(variant)), "Replayed (left "
                    + (variant instanceof Variant.Seeded ? "without the fault, right with it" : "the reference, right the variant")
                    + "):", p -> ReportPictures.where(p) + ": " + p.run().faults().get(faults.indexOf(variant)).newAccident()
                    .map(a -> "FOUND by " + a).orElse("FOUND"));
        }
    }
}
