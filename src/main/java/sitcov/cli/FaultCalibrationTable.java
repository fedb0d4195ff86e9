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
import sitcov.oracle.AccidentType;

/** The table {@code faults --calibrate} prints: deterministic, no timings, one row per fault. */
final class FaultCalibrationTable {
    private final long first;
    private final int maps;
    private final Set<Fault> faults;
    private final List<JudgedMap> results;

    FaultCalibrationTable(long first, int maps, Set<Fault> faults, List<JudgedMap> results) {
        this.first = first;
        this.maps = maps;
        this.faults = faults;
        this.results = results;
    }

    void print(PrintStream out) {
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
