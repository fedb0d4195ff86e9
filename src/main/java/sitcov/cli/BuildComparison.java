package sitcov.cli;

import java.io.PrintStream;
import java.lang.reflect.Method;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * {@code bench --vs BUILD}: this build against another, in one JVM, each in a class loader of its
 * own, the same work alternated round by round so that drift in the machine's speed falls on both
 * alike. Reports the median seconds of each and the median of the round-by-round ratio. The other
 * build is driven through the public entry points every build has ({@code MapGenerator.generate},
 * {@code Simulator.run}, {@code MapRunner.judge}, {@code FaultSet.paper}, {@code FaultyRuns}): those
 * that run the builtin car unnamed where a build has them, else those handed its {@code FACTORY}.
 */
final class BuildComparison {
    /** Maps a round of each kind of work: enough for a tenth of a second or more a build. */
    static final int RUN_MAPS = 150;
    static final int JUDGED_MAPS = 25;
    private static final long WARM_UP_SEED = 1_000_000L;

    private final Build mine;
    private final Build theirs;

    private BuildComparison(Build mine, Build theirs) {
        this.mine = mine;
        this.theirs = theirs;
    }

    static BuildComparison of(Path other) throws UsageException {
        Path own;
        try {
            own = Path.of(BuildComparison.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (java.net.URISyntaxException | SecurityException e) {
            throw new UsageException("bench: cannot tell where this build's classes are, to load them apart: " + e.getMessage());
        }
        return new BuildComparison(Build.load("this build", own), Build.load(other.toString(), other));
    }

    /** Alternates {@code rounds} rounds of fault-free runs and of judged maps; prints both comparisons. */
    void run(int rounds, PrintStream out, PrintStream err) {
        run(rounds, RUN_MAPS, JUDGED_MAPS, out, err);
    }

    /** The same with {@code runMaps} fault-free runs and {@code judgedMaps} judged maps a round. */
    void run(int rounds, int runMaps, int judgedMaps, PrintStream out, PrintStream err) {
        err.println("bench: warming both builds up ...");
        mine.runs(WARM_UP_SEED, runMaps);
        theirs.runs(WARM_UP_SEED, runMaps);
        mine.judge(WARM_UP_SEED, judgedMaps);
        theirs.judge(WARM_UP_SEED, judgedMaps);
        out.printf(Locale.ROOT, "sitcov bench --vs: this build against %s, one JVM, %d alternated rounds%n%n",
                theirs.name, rounds);
        compare("fault-free runs of maps 1.." + runMaps, rounds, runMaps, err, out, false);
        compare("maps 1.." + judgedMaps + " judged with the PAPER faults (until verdict)", rounds, judgedMaps, err, out,
                true);
        out.println();
        out.println("A ratio below 1 means this build is faster. The ratio is taken round by round, so drift in the");
        out.println("machine's speed falls on both builds alike; a wide min-max says the machine was noisy.");
    }

    private void compare(String work, int rounds, int maps, PrintStream err, PrintStream out, boolean judged) {
        double[] a = new double[rounds];
        double[] b = new double[rounds];
        double[] ratio = new double[rounds];
        for (int r = 0; r < rounds; r++) {
            err.println("bench: " + work + ", round " + (r + 1) + " of " + rounds + " ...");
            a[r] = judged ? mine.judge(1, maps) : mine.runs(1, maps);
            b[r] = judged ? theirs.judge(1, maps) : theirs.runs(1, maps);
            ratio[r] = a[r] / b[r];
        }
        Arrays.sort(a);
        Arrays.sort(b);
        Arrays.sort(ratio);
        out.printf(Locale.ROOT, "  %s:%n    this build %.3f s, the other %.3f s (medians); this / other %.3f (min %.3f, max %.3f)%n",
                work, a[rounds / 2], b[rounds / 2], ratio[rounds / 2], ratio[0], ratio[rounds - 1]);
    }

    /** One build's entry points, reached through its own class loader. */
    private static final class Build {
        private final String name;
        private final Method generate;
        private final Method run;
        /** The arguments {@link #run} takes after the map and seed: none, or those naming the builtin car. */
        private final Object[] runTail;
        private final Method judge;
        private final Object[] judgeTail;
        private final List<Object> paper;
        private final Object untilVerdict;
        /** Keeps the JIT from dropping work whose result nobody reads. */
        private long sink;

        private Build(String name, Method generate, Method run, Object[] runTail, Method judge, Object[] judgeTail,
                      List<Object> paper, Object untilVerdict) {
            this.name = name;
            this.generate = generate;
            this.run = run;
            this.runTail = runTail;
            this.judge = judge;
            this.judgeTail = judgeTail;
            this.paper = paper;
            this.untilVerdict = untilVerdict;
        }

        @SuppressWarnings("unchecked")
        static Build load(String name, Path classes) throws UsageException {
            try {
                URLClassLoader loader = new URLClassLoader(new URL[] {classes.toUri().toURL()},
                        ClassLoader.getPlatformClassLoader());
                Class<?> map = loader.loadClass("sitcov.world.WorldMap");
                Class<?> length = loader.loadClass("sitcov.judge.FaultyRuns");
                List<Object> paper = new ArrayList<>((Set<Object>) loader.loadClass("sitcov.faults.FaultSet")
                        .getMethod("paper").invoke(null));
                paper.sort(null);
                Method generate = loader.loadClass("sitcov.world.MapGenerator").getMethod("generate", long.class);
                Class<?> simulator = loader.loadClass("sitcov.judge.Simulator");
                Class<?> mapRunner = loader.loadClass("sitcov.judge.MapRunner");
                Object untilVerdict = length.getField("UNTIL_VERDICT").get(null);
                try {
                    // a build whose entry points run the builtin car unnamed
                    return new Build(name, generate, simulator.getMethod("run", map, long.class), new Object[0],
                            mapRunner.getMethod("judge", map, long.class, List.class, length), new Object[0], paper,
                            untilVerdict);
                } catch (NoSuchMethodException named) {
                    // a build that is handed the controller: its builtin car's factory
                    Class<?> factory = loader.loadClass("sitcov.control.ControllerFactory");
                    Class<?> observer = loader.loadClass("sitcov.judge.RunObserver");
                    Object builtin = loader.loadClass("sitcov.builtin.BuiltinCar").getField("FACTORY").get(null);
                    return new Build(name, generate,
                            simulator.getMethod("run", map, long.class, Set.class, observer, factory),
                            new Object[] {Set.of(), observer.getField("NONE").get(null), builtin},
                            mapRunner.getMethod("judge", map, long.class, List.class, length, factory),
                            new Object[] {builtin}, paper, untilVerdict);
                }
            } catch (MalformedURLException | ReflectiveOperationException | ClassCastException e) {
                throw new UsageException("bench: --vs " + name + " is not a sitcov build this bench can drive (a folder of"
                        + " classes such as target/classes, or a jar, of any sitcov build): " + e);
            }
        }

        /** Seconds to run maps first.. fault-free. */
        double runs(long first, int maps) {
            return time(first, maps, false);
        }

        /** Seconds to judge maps first.. with the PAPER faults. */
        double judge(long first, int maps) {
            return time(first, maps, true);
        }

        /** {@code first}, then {@code tail}: an entry point's arguments. */
        private static Object[] with(Object[] tail, Object... first) {
            Object[] all = Arrays.copyOf(first, first.length + tail.length);
            System.arraycopy(tail, 0, all, first.length, tail.length);
            return all;
        }

        private double time(long first, int maps, boolean judged) {
            try {
                long start = System.nanoTime();
                for (long seed = first; seed < first + maps; seed++) {
                    Object world = generate.invoke(null, seed);
                    Object result = judged ? judge.invoke(null, with(judgeTail, world, seed, paper, untilVerdict))
                            : run.invoke(null, with(runTail, world, seed));
                    sink += result.hashCode();
                }
                return (System.nanoTime() - start) / 1e9;
            } catch (ReflectiveOperationException e) {
                throw new IllegalStateException("bench --vs: " + name + " failed: " + e.getCause(), e);
            }
        }
    }
}
