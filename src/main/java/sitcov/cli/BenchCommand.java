package sitcov.cli;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import sitcov.builtin.BuiltinCar;
import sitcov.control.ControllerFactory;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.judge.FaultyRuns;
import sitcov.judge.MapRunner;
import sitcov.judge.RunObserver;
import sitcov.judge.Simulator;
import sitcov.oracle.RunResult;
import sitcov.world.Layout;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * {@code bench}: how fast sitcov is on this machine, on one thread, after a warm-up: simulated
 * ticks and runs per second over fault-free runs of maps 1..K, and candidate maps (layouts, what
 * the coverage driver generates per candidate) per second. Prints the speed targets (src/README.md, "Speed") beside.
 * The only command that reads the clock for its results: timing is its point.
 */
final class BenchCommand implements Command {
    /** Enough for a steady figure; more only takes longer. */
    static final int MAX_MAPS = 100_000;
    static final int MAX_CANDIDATES = 10_000_000;

    static final int DEFAULT_MAPS = 200;
    static final int DEFAULT_CANDIDATES = 20_000;
    static final int DEFAULT_JUDGED = 40;
    /** Alternated rounds of judging forked and whole; the medians are shown. */
    private static final int FORK_ROUNDS = 3;
    static final int MAX_JUDGED = 10_000;
    private static final long WARM_UP_SEED = 1_000_000L;
    static final int DEFAULT_ROUNDS = 7;
    static final int MAX_ROUNDS = 1000;
    static final int DEFAULT_PROTOCOL_MAPS = 12;
    /** Keeps the JIT from dropping work whose result nobody reads. */
    private static volatile long sink;

    @Override
    public String name() {
        return "bench";
    }

    @Override
    public String synopsis() {
        return "[--maps K (default: " + DEFAULT_MAPS + ")] [--candidates N (default: " + DEFAULT_CANDIDATES + ")]"
                + " [--judged J (default: " + DEFAULT_JUDGED + ")] | --vs BUILD [--rounds R (default: " + DEFAULT_ROUNDS + ")]"
                + " | --protocol [--maps K (default: " + DEFAULT_PROTOCOL_MAPS + ")]";
    }

    @Override
    public String summary() {
        return "measure ticks, runs, candidate maps and judged maps per second (one thread, after a warm-up);"
                + " --vs: this build against another build's classes, alternated in one JVM";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--maps", "--candidates", "--judged", "--vs", "--rounds"),
                Set.of("--protocol"));
        options.noPositional();
        if (options.has("--protocol")) {
            for (String other : List.of("--candidates", "--judged", "--vs", "--rounds")) {
                if (options.has(other)) {
                    throw new UsageException("bench: --protocol times the controller protocol alone; leave out " + other + ".");
                }
            }
            return ProtocolBench.run(options.count("--maps", 1, MAX_MAPS).orElse(DEFAULT_PROTOCOL_MAPS), out, err);
        }
        if (options.value("--vs").isPresent()) {
            if (options.value("--maps").isPresent() || options.value("--candidates").isPresent()
                    || options.value("--judged").isPresent()) {
                throw new UsageException("bench: --vs compares two builds on fixed work; leave out --maps, --candidates"
                        + " and --judged (or leave out --vs).");
            }
            Path other = Path.of(options.value("--vs").get());
            if (!Files.isDirectory(other) && !Files.isRegularFile(other)) {
                throw new UsageException("bench: --vs " + other + " does not exist; give another build's classes folder"
                        + " (e.g. /tmp/before/target/classes) or jar.");
            }
            int rounds = options.count("--rounds", 1, MAX_ROUNDS).orElse(DEFAULT_ROUNDS);
            BuildComparison.of(other).run(rounds, out, err);
            return ExitCode.OK;
        }
        if (options.value("--rounds").isPresent()) {
            throw new UsageException("bench: --rounds goes with --vs BUILD.");
        }
        int maps = options.count("--maps", 1, MAX_MAPS).orElse(DEFAULT_MAPS);
        int candidates = options.count("--candidates", 1, MAX_CANDIDATES).orElse(DEFAULT_CANDIDATES);
        int judged = options.count("--judged", 1, MAX_JUDGED).orElse(DEFAULT_JUDGED);
        print(out, measure(maps, candidates, judged, err));
        return ExitCode.OK;
    }

    /** What {@link #measure} timed: runs of maps 1..maps, candidate maps, and judged maps three ways. */
    private record Figures(int maps, int candidates, int judged, int warmRuns, int warmCandidates, long movingCars,
                           long ticks, long runNanos, long layoutNanos, double untilVerdict, double toEnd, Forking forking) {
    }

    /** Seconds and ticks a judged map with all twenty faults, forked and whole (medians of the alternated rounds). */
    private record Forking(double forkedSeconds, double wholeSeconds, long forkedTicks, long wholeTicks) {
    }

    private static Figures measure(int maps, int candidates, int judged, PrintStream err) {
        // the JIT needs a few hundred runs before the tick settles: fewer measure the compiler, not the car
        int warmRuns = Math.min(2 * maps, 400);
        int warmCandidates = Math.min(candidates, 5_000);
        err.println("bench: warming up (" + warmRuns + " runs, " + warmCandidates + " candidate maps) ...");
        for (int i = 0; i < warmRuns; i++) {
            sink += Simulator.run(MapGenerator.generate(WARM_UP_SEED + i), WARM_UP_SEED + i, Set.of(), RunObserver.NONE,
                    BuiltinCar.FACTORY).result().ticks();
        }
        candidateNanos(WARM_UP_SEED, warmCandidates);

        err.println("bench: timing " + maps + " fault-free runs and " + candidates + " candidate maps ...");
        List<WorldMap> worlds = new ArrayList<>(maps);
        long movingCars = 0;
        for (long seed = 1; seed <= maps; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            worlds.add(map);
            movingCars += map.movingCars().size();
        }
        long ticks = 0;
        long runNanos = 0;
        for (WorldMap map : worlds) {
            long start = System.nanoTime();
            RunResult result = Simulator.run(map, map.seed(), Set.of(), RunObserver.NONE, BuiltinCar.FACTORY).result();
            runNanos += System.nanoTime() - start;
            ticks += result.ticks();
        }
        sink += ticks;
        long layoutNanos = candidateNanos(1, candidates);
        err.println("bench: judging maps 1.." + judged + " with the PAPER faults, faulty runs until their verdict and to the end ...");
        List<WorldMap> judgedMaps = worlds.subList(0, Math.min(judged, worlds.size()));
        while (judgedMaps.size() < judged) {
            judgedMaps = new ArrayList<>(judgedMaps);
            judgedMaps.add(MapGenerator.generate(judgedMaps.size() + 1));
        }
        double untilVerdict = judgeSeconds(judgedMaps, FaultyRuns.UNTIL_VERDICT) / judged;
        double toEnd = judgeSeconds(judgedMaps, FaultyRuns.TO_END) / judged;
        err.println("bench: judging maps 1.." + judged + " with all twenty faults, forked and run whole ...");
        return new Figures(maps, candidates, judged, warmRuns, warmCandidates, movingCars, ticks, runNanos, layoutNanos,
                untilVerdict, toEnd, forking(judgedMaps));
    }

    private static Forking forking(List<WorldMap> judgedMaps) {
        int judged = judgedMaps.size();
        List<Fault> all = List.of(Fault.values());
        ControllerFactory whole = BuiltinCar.FACTORY.unforked();
        // both warmed on a map, then alternated round by round (the first of a pair runs on a colder cache)
        stepped(judgedMaps.subList(0, 1), all, BuiltinCar.FACTORY);
        stepped(judgedMaps.subList(0, 1), all, whole);
        double[] forkedRounds = new double[FORK_ROUNDS];
        double[] wholeRounds = new double[FORK_ROUNDS];
        long forkedTicks = 0;
        long wholeTicks = 0;
        for (int r = 0; r < FORK_ROUNDS; r++) {
            long start = System.nanoTime();
            if (r % 2 == 0) {
                forkedTicks = stepped(judgedMaps, all, BuiltinCar.FACTORY);
                long between = System.nanoTime();
                wholeTicks = stepped(judgedMaps, all, whole);
                forkedRounds[r] = (between - start) / 1e9 / judged;
                wholeRounds[r] = (System.nanoTime() - between) / 1e9 / judged;
            } else {
                wholeTicks = stepped(judgedMaps, all, whole);
                long between = System.nanoTime();
                forkedTicks = stepped(judgedMaps, all, BuiltinCar.FACTORY);
                wholeRounds[r] = (between - start) / 1e9 / judged;
                forkedRounds[r] = (System.nanoTime() - between) / 1e9 / judged;
            }
        }
        return new Forking(median(forkedRounds), median(wholeRounds), forkedTicks, wholeTicks);
    }

    private static void print(PrintStream out, Figures f) {
        double runSeconds = f.runNanos() / 1e9;
        double layoutSeconds = f.layoutNanos() / 1e9;
        double microsPerTick = f.runNanos() / 1e3 / f.ticks();
        double per20000 = layoutSeconds * DEFAULT_CANDIDATES / f.candidates();
        Forking k = f.forking();
        out.printf(Locale.ROOT, "sitcov bench: one thread, after a warm-up of %d runs and %d candidate maps%n%n",
                f.warmRuns(), f.warmCandidates());
        out.printf(Locale.ROOT, "  %-36s %12s   %s%n", "measure", "figure", "target");
        line(out, "simulated ticks per second", String.format(Locale.ROOT, "%.0f", f.ticks() / runSeconds),
                ">= 125000 (follows from the tick time)");
        line(out, "microseconds per tick", String.format(Locale.ROOT, "%.2f", microsPerTick),
                "<= 8 with 15 moving cars " + verdict(microsPerTick <= 8));
        line(out, "mean moving cars per map", String.format(Locale.ROOT, "%.1f", (double) f.movingCars() / f.maps()),
                "15 (a typical map)");
        line(out, "runs per second", String.format(Locale.ROOT, "%.2f", f.maps() / runSeconds), "");
        line(out, "mean ticks per run", String.format(Locale.ROOT, "%.1f", (double) f.ticks() / f.maps()), "");
        line(out, "candidate maps per second", String.format(Locale.ROOT, "%.0f", f.candidates() / layoutSeconds),
                "> 10000 (follows from the next line)");
        line(out, "seconds for 20000 candidates", String.format(Locale.ROOT, "%.3f", per20000),
                "< 2 " + verdict(per20000 < 2) + (f.candidates() == DEFAULT_CANDIDATES ? ""
                        : " (extrapolated from " + f.candidates() + ")"));
        line(out, "seconds a judged map, until verdict", String.format(Locale.ROOT, "%.4f", f.untilVerdict()),
                "fault-free run + 7 PAPER faulty runs (faulty_runs=until-verdict)");
        line(out, "seconds a judged map, to the end", String.format(Locale.ROOT, "%.4f", f.toEnd()),
                "the same, faulty runs driven to the Target or the timeout");
        line(out, "seconds a judged map, ALL, forked", String.format(Locale.ROOT, "%.4f", k.forkedSeconds()),
                "fault-free run + all twenty faulty runs (until verdict), each from where its fault departs");
        line(out, "seconds a judged map, ALL, whole", String.format(Locale.ROOT, "%.4f", k.wholeSeconds()),
                String.format(Locale.ROOT, "the same, every faulty run from tick 0 (--fork off): forked / whole %.3f",
                        k.forkedSeconds() / k.wholeSeconds()));
        line(out, "ticks a judged map, ALL, forked", String.format(Locale.ROOT, "%.0f", (double) k.forkedTicks() / f.judged()),
                String.format(Locale.ROOT, "against %.0f run whole: %.3f of them", (double) k.wholeTicks() / f.judged(),
                        (double) k.forkedTicks() / k.wholeTicks()));
        out.println();
        out.printf(Locale.ROOT, "Runs: maps 1..%d, internal seed = external seed, no faults, %d ticks in %.2f s."
                + " Candidates: MapGenerator.layout of seeds 1..%d in %.3f s.%n", f.maps(), f.ticks(), runSeconds,
                f.candidates(), layoutSeconds);
        out.printf(Locale.ROOT, "Judged maps: 1..%d, each run fault-free and once per PAPER fault, as an experiment does.%n",
                f.judged());
    }

    private static double judgeSeconds(List<WorldMap> maps, FaultyRuns length) {
        List<Fault> paper = FaultSet.paper().stream().sorted().toList();
        long start = System.nanoTime();
        for (WorldMap map : maps) {
            sink += MapRunner.judge(map, map.seed(), paper, length, BuiltinCar.FACTORY).ticks();
        }
        return (System.nanoTime() - start) / 1e9;
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        java.util.Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }

    /** Judges {@code maps} with {@code faults} as an experiment does; the ticks the judging stepped. */
    private static long stepped(List<WorldMap> maps, List<Fault> faults, ControllerFactory car) {
        long ticks = 0;
        for (WorldMap map : maps) {
            ticks += MapRunner.ticksStepped(map, map.seed(), faults, FaultyRuns.UNTIL_VERDICT, car);
        }
        return ticks;
    }

    private static long candidateNanos(long firstSeed, int count) {
        long roads = 0;
        long start = System.nanoTime();
        for (int i = 0; i < count; i++) {
            Layout layout = MapGenerator.layout(firstSeed + i);
            roads += layout.roads().size();
        }
        long nanos = System.nanoTime() - start;
        sink += roads;
        return nanos;
    }

    static String verdict(boolean met) {
        return met ? "[met]" : "[NOT met]";
    }

    private static void line(PrintStream out, String label, String figure, String target) {
        out.println(String.format(Locale.ROOT, "  %-36s %12s   %s", label, figure, target).stripTrailing());
    }
}
