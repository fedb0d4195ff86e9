package sitcov.cli;

import java.io.PrintStream;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultVerdict;
import sitcov.judge.JudgedMap;
import sitcov.judge.Proportion;
import sitcov.judge.Variant;
import sitcov.oracle.Failure;
import sitcov.seam.SeamFault;
import sitcov.oracle.AccidentType;

/** The table {@code faults --calibrate} prints: deterministic, no timings, one row per fault. */
final class FaultCalibrationTable {
    private final long first;
    private final int maps;
    private final Set<Fault> faults;
    private final List<JudgedMap> results;
    private final List<Variant> variants;
    private final String controller;

    FaultCalibrationTable(long first, int maps, Set<Fault> faults, List<JudgedMap> results) {
        this(first, maps, faults, results, List.of(), "builtin");
    }

    /** The table of seam faults {@code variants}, judged on {@code controller}. */
    FaultCalibrationTable(long first, int maps, List<Variant> variants, String controller, List<JudgedMap> results) {
        this(first, maps, Set.of(), results, variants, controller);
    }

    private FaultCalibrationTable(long first, int maps, Set<Fault> faults, List<JudgedMap> results, List<Variant> variants,
                                  String controller) {
        this.first = first;
        this.maps = maps;
        this.faults = faults;
        this.results = results;
        this.variants = variants;
        this.controller = controller;
    }

    void print(PrintStream out) {
        if (!variants.isEmpty()) {
            printSeams(out);
            return;
        }
        long background = results.stream().filter(m -> m.faultFree().hasAccident()).count();
        out.printf(Locale.ROOT, "Fault calibration: %d maps (external seeds %d..%d, internal seed = external seed),"
                + " faults %s%n", maps, first, first + maps - 1, FaultSet.format(faults));
        out.printf(Locale.ROOT, "Fault-free runs with any accident: %d (%.1f%%). FOUND = an accident the fault-free"
                + " run of the same seeds lacks;%npaper = any accident in the faulty run (the paper's notion).%n%n",
                background, 100.0 * background / maps);
        out.printf(Locale.ROOT, "%3s  %-34s %8s %9s %7s  %-15s %7s  %-60s  %s%n", "id", "fault", "reached", "effective",
                "FOUND", "95% CI", "paper", "FOUND by", "e.g. map");
        int column = 0;
        for (Fault fault : faults.stream().sorted().toList()) {
            row(out, fault, column++);
        }
        out.println();
        String args = "faults --calibrate --maps " + maps + " --seed " + first + " --faults " + FaultSet.format(faults);
        out.println("Replay a map: " + Main.LAUNCHER + " simulate --seed S --faults ID --png run.png"
                + " (and without --faults for the fault-free run)");
        out.println("Reproduce: " + Main.LAUNCHER + " " + args);
    }

    /** The seam faults' table: one row per fault, its id {@code seam:NAME}, judged on the controller named. */
    private void printSeams(PrintStream out) {
        long background = results.stream().filter(m -> m.faultFree().failed()).count();
        String set = variants.size() == SeamFault.values().length ? SeamFault.ALL
                : String.join(",", variants.stream().map(Variant::spec).toList());
        out.printf(Locale.ROOT, "Seam fault calibration: %d maps (external seeds %d..%d, internal seed = external seed),"
                + " controller %s%n", maps, first, first + maps - 1, controller);
        out.printf(Locale.ROOT, "Reference runs that failed: %d (%.1f%%). FOUND = a failure the reference run of the same"
                + " seeds lacks;%npaper = reached and any failure in the faulty run (the paper's notion).%n%n",
                background, 100.0 * background / maps);
        out.printf(Locale.ROOT, "%-28s %8s %9s %7s  %-15s %7s  %-60s  %s%n", "id", "reached", "effective",
                "FOUND", "95% CI", "paper", "FOUND by", "e.g. map");
        for (int column = 0; column < variants.size(); column++) {
            Tally t = tally(column);
            out.printf(Locale.ROOT, "%-28s %7.1f%% %8.1f%% %6.1f%%  %-15s %6.1f%%  %-60s  %s%n", variants.get(column).spec(),
                    pct(t.reached), pct(t.effective), 100 * t.share().share(), t.ci(), pct(t.paper), t.types(),
                    t.example < 0 ? "-" : t.example);
        }
        out.println();
        String args = "faults --calibrate --maps " + maps + " --seed " + first + " --faults " + set
                + (controller.equals("builtin") ? "" : " --controller '" + controller + "'");
        out.println("Reproduce: " + Main.PROGRAM + " " + args);
    }

    /** What one column's verdicts add up to. */
    private record Tally(int reached, int effective, int found, int paper, long example, Map<String, Integer> by, int maps) {
        public Proportion share() {
            return new Proportion(found, maps);
        }

        public String ci() {
            return String.format(Locale.ROOT, "[%.1f, %.1f]", 100 * share().wilsonLow(), 100 * share().wilsonHigh());
        }

        public String types() {
            return by.isEmpty() ? "-" : by.entrySet().stream().map(e -> e.getKey() + " " + e.getValue())
                    .collect(Collectors.joining(", "));
        }
    }

    private Tally tally(int column) {
        int reached = 0;
        int effective = 0;
        int found = 0;
        int paper = 0;
        long example = -1;
        Map<String, Integer> by = new java.util.TreeMap<>();
        for (JudgedMap m : results) {
            FaultVerdict v = m.verdicts().get(column);
            reached += v.reached() ? 1 : 0;
            effective += v.effective() ? 1 : 0;
            paper += v.foundByPaperNotion() ? 1 : 0;
            if (v.detection().found()) {
                found++;
                Failure f = v.newFailure().orElseThrow();
                by.merge(f.ofController() ? f.column() : AccidentType.valueOf(f.name()).word(), 1, Integer::sum);
                if (example < 0 && !m.faultFree().failed()) {
                    example = v.externalSeed();
                }
            }
        }
        return new Tally(reached, effective, found, paper, example, by, maps);
    }

    private void row(PrintStream out, Fault fault, int column) {
        int reached = 0;
        int effective = 0;
        int found = 0;
        int paper = 0;
        long example = -1;
        Map<AccidentType, Integer> by = new EnumMap<>(AccidentType.class);
        for (JudgedMap m : results) {
            FaultVerdict v = m.verdicts().get(column);
            reached += v.reached() ? 1 : 0;
            effective += v.effective() ? 1 : 0;
            paper += v.foundByPaperNotion() ? 1 : 0;
            if (v.detection().found()) {
                found++;
                by.merge(v.newAccident().orElseThrow().type(), 1, Integer::sum);
                if (example < 0 && !m.faultFree().hasAccident()) {
                    example = v.externalSeed();
                }
            }
        }
        Proportion p = new Proportion(found, maps);
        String ci = String.format(Locale.ROOT, "[%.1f, %.1f]", 100 * p.wilsonLow(), 100 * p.wilsonHigh());
        String types = by.isEmpty() ? "-" : by.entrySet().stream()
                .map(e -> e.getKey().word() + " " + e.getValue()).collect(Collectors.joining(", "));
        out.printf(Locale.ROOT, "%3d  %-34s %7.1f%% %8.1f%% %6.1f%%  %-15s %6.1f%%  %-60s  %s%n", fault.id(), fault.label(),
                pct(reached), pct(effective), 100 * p.share(), ci, pct(paper), types, example < 0 ? "-" : example);
    }

    private double pct(int count) {
        return 100.0 * count / maps;
    }
}
