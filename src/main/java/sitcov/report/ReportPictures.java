package sitcov.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import sitcov.analysis.OwnFailures;
import sitcov.experiment.MapRun;
import sitcov.judge.Notion;
import sitcov.judge.Variant;
import sitcov.render.ReplayGallery.Pictured;

/**
 * Which failures and findings the report draws. Every one is a candidate: each map on which the reference
 * failed by itself, and each variant's finding. A folder may hold hundreds, so at most {@link #MOST} are
 * drawn, taken in turns: the first own failure and each variant's first finding, then the second of each,
 * and so on, each in runs.csv order, until {@link #MOST} are taken. A small folder has all of them drawn;
 * a large one a few of each kind, and its first finding of every variant.
 */
record ReportPictures(List<Pictured> drawn, int ownFailures, List<Integer> findings) {
    /** The most pictures one report draws: each takes a replay of two runs and some 100 kB. */
    static final int MOST = 24;

    /** The pictures of an experiment of {@code variants} whose judged maps are {@code inOrder}, as runs.csv lists them. */
    static ReportPictures of(List<Variant> variants, List<MapRun> inOrder) {
        int perMap = 1 + variants.size();
        List<List<Pictured>> turns = new ArrayList<>();
        List<Pictured> own = new ArrayList<>();
        for (int m = 0; m < inOrder.size(); m++) {
            if (OwnFailures.failed(inOrder.get(m))) {
                own.add(new Pictured(m * perMap + 1, inOrder.get(m), Optional.empty(), false));
            }
        }
        turns.add(own);
        List<Integer> findings = new ArrayList<>();
        for (int f = 0; f < variants.size(); f++) {
            List<Pictured> found = new ArrayList<>();
            for (int m = 0; m < inOrder.size(); m++) {
                MapRun run = inOrder.get(m);
                if (run.faults().get(f).found(Notion.DIFFERENTIAL)) {
                    found.add(new Pictured(m * perMap + f + 2, run, Optional.of(variants.get(f)), found.isEmpty()));
                }
            }
            turns.add(found);
            findings.add(found.size());
        }
        List<Pictured> drawn = new ArrayList<>();
        for (int turn = 0; drawn.size() < MOST; turn++) {
            boolean any = false;
            for (List<Pictured> kind : turns) {
                if (turn < kind.size() && drawn.size() < MOST) {
                    drawn.add(kind.get(turn));
                    any = true;
                }
            }
            if (!any) {
                break;
            }
        }
        return new ReportPictures(List.copyOf(drawn), own.size(), List.copyOf(findings));
    }

    /** The pictures of the reference's own failures, or of variant {@code variant}'s findings, in runs.csv order. */
    List<Pictured> of(Optional<Variant> variant) {
        return drawn.stream().filter(p -> p.variant().equals(variant)).sorted(java.util.Comparator.comparingInt(Pictured::row))
                .toList();
    }

    /** Failures and findings in all. */
    int candidates() {
        return ownFailures + findings.stream().mapToInt(Integer::intValue).sum();
    }

    /** The rule, as HTML for the page, with how many of how many are drawn and how to draw the rest. */
    String rule(boolean builtinCar) {
        return "Pictures: " + drawn.size() + " of the " + candidates() + " failures and findings of this folder are drawn"
                + " (at most " + MOST + ", taken in turns: the first own failure and the first finding of each variant,"
                + " then the second of each, and so on, in runs.csv order), each replayed from its recorded commands"
                + (builtinCar ? " (a seeded fault's run by the builtin car run again, to the end of the faulty run)" : "")
                + ". Any other is drawn by the replay command of its row, <var>N</var> of runs.csv: <code>java -jar \"$"
                + ReportFaultMaps.JAR + "\" replay . --row <var>N</var> --png <var>FILE</var></code>";
    }

    /**
     * The pictures {@code shown} that were drawn, under {@code lead} (HTML), side by side, each captioned by
     * {@code caption} and opening at full size; nothing when none was drawn.
     */
    static void append(StringBuilder h, java.nio.file.Path folder, List<Pictured> shown, String lead,
                       java.util.function.Function<Pictured, String> caption) {
        List<Pictured> there = shown.stream().filter(p -> java.nio.file.Files.isRegularFile(p.file(folder))).toList();
        if (there.isEmpty()) {
            return;
        }
        h.append("<p>").append(lead).append("</p><div class=\"shots\">");
        for (Pictured p : there) {
            String text = HtmlReport.esc(caption.apply(p));
            h.append("<figure><a href=\"").append(p.name()).append("\"><img loading=\"lazy\" src=\"").append(p.name())
                    .append("\" alt=\"").append(text).append("\"></a><figcaption>").append(text).append("</figcaption></figure>");
        }
        h.append("</div>\n");
    }

    /** Where a row's run is: "row 14: replication 0, random, map 3". */
    static String where(Pictured p) {
        return "row " + p.row() + ": replication " + p.run().replication() + ", " + p.run().driver() + ", map "
                + p.run().mapIndex();
    }
}
