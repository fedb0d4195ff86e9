package sitcov.cli;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;
import sitcov.oracle.RunResult;

/**
 * The fault-free calibration of {@code simulate --maps N}: tallies run results and prints the
 * summary table (deterministic: no timings in it).
 */
final class Calibration {
    private static final int SEEDS_LISTED = 20;

    private final long firstSeed;
    private final int maps;
    private final boolean summaryOnly;
    private int runs;
    private int reached;
    private int withAccident;
    private int withAccidentBesidesTimeout;
    private long ticks;
    private long excused;
    private int runsClamped;
    private long clampedTicks;
    private final Map<AccidentType, Long> events = new EnumMap<>(AccidentType.class);
    private final Map<AccidentType, Integer> runsWith = new EnumMap<>(AccidentType.class);
    private final List<Long> accidentSeeds = new ArrayList<>();
    private final List<Long> timeoutSeeds = new ArrayList<>();
    private final Map<Outcome, Integer> controllerFailed = new EnumMap<>(Outcome.class);
    private final List<Long> controllerSeeds = new ArrayList<>();
    private final String controller;
    private final boolean plantedFaults;

    /**
     * The calibration of the controller {@code controller} names: the options that run it again, as
     * {@link #controllerArgs} gives them (empty for the builtin car); {@code plantedFaults} when it is
     * the builtin car with faults switched on ({@code builtin:FAULTS}), calibrated faults and all.
     */
    Calibration(long firstSeed, int maps, boolean summaryOnly, String controller, boolean plantedFaults) {
        this.firstSeed = firstSeed;
        this.maps = maps;
        this.summaryOnly = summaryOnly;
        this.controller = controller;
        this.plantedFaults = plantedFaults;
        for (AccidentType t : AccidentType.values()) {
            events.put(t, 0L);
            runsWith.put(t, 0);
        }
    }

    void add(RunResult r) {
        runs++;
        ticks += r.ticks();
        if (r.outcome() == Outcome.TARGET_REACHED) {
            reached++;
        }
        if (r.hasAccident()) {
            withAccident++;
        }
        if (r.outcome() == Outcome.TIMEOUT && timeoutSeeds.size() < SEEDS_LISTED) {
            timeoutSeeds.add(r.externalSeed());
        }
        if (r.accidents().stream().anyMatch(a -> a.type() != AccidentType.TIMEOUT)) {
            withAccidentBesidesTimeout++;
            if (accidentSeeds.size() < SEEDS_LISTED) {
                accidentSeeds.add(r.externalSeed());
            }
        }
        if (r.controllerFailure().isPresent()) {
            controllerFailed.merge(r.outcome(), 1, Integer::sum);
            if (controllerSeeds.size() < SEEDS_LISTED) {
                controllerSeeds.add(r.externalSeed());
            }
        }
        if (r.clampedTicks() > 0) {
            runsClamped++;
            clampedTicks += r.clampedTicks();
        }
        excused += r.excusedContacts().values().stream().mapToInt(Integer::intValue).sum();
        for (Map.Entry<AccidentType, Long> e : r.countsByType().entrySet()) {
            if (e.getValue() > 0) {
                events.merge(e.getKey(), e.getValue(), Long::sum);
                runsWith.merge(e.getKey(), 1, Integer::sum);
            }
        }
    }

    void printTable(PrintStream out) {
        String kind = plantedFaults ? "Calibration with planted faults" : "Fault-free calibration";
        out.printf(Locale.ROOT, "%s: %d maps, external seeds %d..%d, internal seed = external seed,"
                + " one thread%n%n", kind, runs, firstSeed, firstSeed + runs - 1);
        out.printf(Locale.ROOT, "  %-30s %6d%n", "runs", runs);
        row(out, "reached the Target", reached, "target: at least 99%");
        row(out, "any accident (incl. TIMEOUT)", withAccident, "target: at most 1%");
        row(out, "any accident besides TIMEOUT", withAccidentBesidesTimeout, "");
        // a controller that fails gives no accident and no arrival: its runs are counted here, not lost
        int failed = controllerFailed.values().stream().mapToInt(Integer::intValue).sum();
        if (failed > 0) {
            row(out, "controller failed", failed, "");
            for (Map.Entry<Outcome, Integer> e : controllerFailed.entrySet()) {
                row(out, "  " + e.getKey(), e.getValue(), "");
            }
            row(out, "any failure incl. controller", withAccident + failed, "");
        }
        if (runsClamped > 0) {
            // the world clamped commands beyond the car's limits (never the builtin car's): shown only then
            out.printf(Locale.ROOT, "  %-30s %6d %6.1f%%   (%d ticks in all)%n", "runs with commands clamped", runsClamped,
                    share(runsClamped), clampedTicks);
        }
        out.printf(Locale.ROOT, "  %-30s %8.1f%n", "mean ticks", runs == 0 ? 0.0 : (double) ticks / runs);
        out.printf(Locale.ROOT, "  %-30s %6d %6.3f a run   (target: at most 0.01)%n", "excused contacts (events)",
                excused, runs == 0 ? 0.0 : (double) excused / runs);
        out.println();
        out.printf(Locale.ROOT, "  %-30s %6s  %s%n", "accident type", "events", "runs with it");
        for (AccidentType t : AccidentType.values()) {
            out.printf(Locale.ROOT, "  %-30s %6d  %6d %6.1f%%%n", t, events.get(t), runsWith.get(t), share(runsWith.get(t)));
        }
        out.println();
        listSeeds(out, "Seeds with an accident besides TIMEOUT", accidentSeeds, withAccidentBesidesTimeout);
        listSeeds(out, "Seeds that timed out", timeoutSeeds, runs - reached - failed);
        listSeeds(out, "Seeds where the controller failed", controllerSeeds, failed);
        String args = "simulate --maps " + maps + " --seed " + firstSeed + (summaryOnly ? " --summary" : "") + controller;
        out.println("Reproduce: " + Main.LAUNCHER + " " + args);
    }

    private void listSeeds(PrintStream out, String what, List<Long> seeds, int total) {
        if (!seeds.isEmpty()) {
            out.println(what + (total > seeds.size() ? " (first " + seeds.size() + ")" : "") + ": "
                    + String.join(", ", seeds.stream().map(String::valueOf).toList())
                    + "; see one with: simulate --seed S" + controller + " --png run.png");
        }
    }

    /**
     * The options that run {@code controller} again as it ran here: none for the builtin car, else
     * {@code --controller} quoted for a POSIX shell, and the per-tick timeout when it was not the default.
     */
    static String controllerArgs(String controller, java.util.OptionalInt tickTimeout) {
        String args = controller.equals("builtin") ? "" : " --controller " + shellQuoted(controller);
        return args + (tickTimeout.isPresent() ? " --tick-timeout " + tickTimeout.getAsInt() : "");
    }

    /** {@code text} as one word of a POSIX shell, always quoted. */
    static String shellQuoted(String text) {
        return sitcov.results.ShellWord.quoted(text);
    }

    private void row(PrintStream out, String label, int count, String target) {
        out.printf(Locale.ROOT, "  %-30s %6d %6.1f%%%s%n", label, count, share(count),
                target.isEmpty() ? "" : "   (" + target + ")");
    }

    private double share(int count) {
        return runs == 0 ? 0.0 : 100.0 * count / runs;
    }
}
