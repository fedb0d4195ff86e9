package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.judge.BatchedRuns;
import sitcov.judge.LiveRun;
import sitcov.judge.RunObserver;
import sitcov.judge.RunRecord;
import sitcov.judge.Simulator;
import sitcov.protocol.BatchingProxy;
import sitcov.protocol.ControllerStartException;
import sitcov.protocol.ExecControllers;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * {@code bench --protocol}: how fast a controller program is driven over the protocol, one run at a
 * time and in batches, to a trivial Python controller; timing is its point.
 */
final class ProtocolBench {
    /** Maps before the timing are drawn from seeds far from the timed ones. */
    private static final long WARM_UP_SEED = 1_000_000L;
    /** Runs over the protocol before the timing: fewer leave the JIT compiling during it. */
    private static final int PROTOCOL_WARM_UP_RUNS = 12;
    /** The batches --protocol times side by side (batched lockstep; 1 is one run at a time). */
    private static final int[] BATCHES = {1, 8, 32};
    /**
     * The trivial controller {@code --protocol} times the protocol with, in Python: it parses every
     * message with the standard json module and answers every observation with one fixed command
     * (stand still, wheel straight), echoing the observation's tick (protocol 2). It asks for no sensor, as a controller that needs none would;
     * with {@code --radar} it asks for the radar's tracks and the LIDAR's obstacles, as the builtin car does.
     */
    static final String CONSTANT_CONTROLLER = String.join("\n",
            "import json, sys",
            "sensors = '[\"radar\",\"obstacles\"]' if sys.argv[1:] == ['--radar'] else '[]'",
            "out = sys.stdout",
            "for line in sys.stdin:",
            "    msg = json.loads(line)",
            "    kind = msg['type']",
            "    if kind == 'hello':",
            "        out.write('{\"type\":\"hello\",\"protocol\":2,\"name\":\"constant\",\"batch\":64,\"sensors\":' + sensors + '}\\n')",
            "    elif kind == 'observation':",
            "        out.write('{\"type\":\"command\",\"tick\":%d,\"speed_change\":0,\"steering\":0}\\n' % msg['tick'])",
            "    elif kind == 'observations':",
            "        out.write('{\"type\":\"commands\",\"items\":[' + ','.join('{\"type\":\"command\",\"tick\":%d,\"run\":%d,"
                    + "\"speed_change\":0,\"steering\":0}' % (o['tick'], o['run']) for o in msg['items']) + ']}\\n')",
            "    else:",
            "        continue",
            "    out.flush()",
            "");

    /** Keeps the JIT from dropping work whose result nobody reads. */
    private static volatile long sink;

    private ProtocolBench() {
    }

    /**
     * Protocol ticks a second to {@link #CONSTANT_CONTROLLER} (python3, a process of its own): the
     * car stands at its start for the whole run (5000 ticks) while the traffic moves round it, so
     * every observation carries the radar tracks and junction signals a real one does. One worker;
     * pin sitcov and the controller to one core with {@code taskset -c 0} to time them sharing it.
     */
    static int run(int maps, PrintStream out, PrintStream err) throws UsageException {
        Path script;
        try {
            script = Files.createTempFile("sitcov-constant-controller", ".py");
            Files.writeString(script, CONSTANT_CONTROLLER);
        } catch (IOException e) {
            err.println("sitcov: bench: could not write the trivial controller to the temporary folder: " + e.getMessage());
            return ExitCode.FAILURE;
        }
        try {
            ProtocolTiming lean = protocolTicksPerSecond(List.of("python3", script.toString()), maps, err);
            ProtocolTiming radar = protocolTicksPerSecond(List.of("python3", script.toString(), "--radar"), maps, err);
            out.printf(Locale.ROOT, "sitcov bench --protocol: one worker, a trivial Python controller (one fixed command)%n%n");
            out.printf(Locale.ROOT, "  %-44s %12s   %s%n", "measure", "figure", "target");
            protocolLine(out, "protocol ticks per second, no sensors", lean.perSecond(),
                    ">= 10000 on one core " + BenchCommand.verdict(lean.perSecond() >= 10_000));
            cpuLine(out, "  CPU a tick, sitcov + controller", lean.cpuMicrosPerTick());
            protocolLine(out, "protocol ticks per second, radar+obstacles", radar.perSecond(), "the builtin car's sensors");
            cpuLine(out, "  CPU a tick, sitcov + controller", radar.cpuMicrosPerTick());
            ProtocolTiming[] batched = new ProtocolTiming[BATCHES.length];
            for (int b = 0; b < BATCHES.length; b++) {
                // batch 1 timed again here, the JIT as warm as for the others
                batched[b] = BATCHES[b] == 1 ? protocolTicksPerSecond(List.of("python3", script.toString()), maps, err)
                        : batchedTicksPerSecond(List.of("python3", script.toString()), maps, BATCHES[b], err);
            }
            out.println();
            out.printf(Locale.ROOT, "Batched lockstep, no sensors (B runs a round trip, max(K, B) runs):%n");
            for (int b = 0; b < BATCHES.length; b++) {
                out.printf(Locale.ROOT, "  batch %d: %.0f ticks a second%s%n", BATCHES[b], batched[b].perSecond(),
                        b == 0 ? "" : String.format(Locale.ROOT, "  (%.1f x batch 1)", batched[b].perSecond()
                                / batched[0].perSecond()));
            }
            out.printf(Locale.ROOT, "  CPU a tick, sitcov + controller:");
            for (int b = 0; b < BATCHES.length; b++) {
                out.printf(Locale.ROOT, "%s batch %d %.1f µs", b == 0 ? "" : ",", BATCHES[b], batched[b].cpuMicrosPerTick());
            }
            out.printf(Locale.ROOT, " (batch %d: %.1f x fewer than batch 1)%n", BATCHES[BATCHES.length - 1],
                    batched[0].cpuMicrosPerTick() / batched[BATCHES.length - 1].cpuMicrosPerTick());
            ProtocolTiming largest = batched[BATCHES.length - 1];
            out.printf(Locale.ROOT, "  target: batch %d >= 5 x batch 1 and >= 50000 ticks a second %s%n",
                    BATCHES[BATCHES.length - 1], BenchCommand.verdict(largest.perSecond() >= 5 * batched[0].perSecond()
                            && largest.perSecond() >= 50_000));
            out.println();
            out.printf(Locale.ROOT, "Runs: maps 1..%d each, the car standing at its start (5000 ticks a run) while the traffic"
                    + " moves round it. Both processes on one core: taskset -c 0 %s bench --protocol%n", maps, Main.LAUNCHER);
            return ExitCode.OK;
        } finally {
            try {
                Files.deleteIfExists(script);
            } catch (IOException e) {
                // a temporary file left behind
            }
        }
    }

    private static void cpuLine(PrintStream out, String label, double micros) {
        out.println(String.format(Locale.ROOT, "  %-44s %9.1f µs   one core to themselves: %.0f ticks a second", label,
                micros, 1e6 / micros));
    }

    private static void protocolLine(PrintStream out, String label, double perSecond, String target) {
        out.println(String.format(Locale.ROOT, "  %-44s %12.0f   %s  (%.1f µs a tick)", label, perSecond, target,
                1e6 / perSecond));
    }

    /** Protocol ticks a second, and CPU a tick, with runs stepped {@code batch} at a time over one process: max(maps, batch) runs. */
    private static ProtocolTiming batchedTicksPerSecond(List<String> command, int maps, int batch, PrintStream err)
            throws UsageException {
        try (ExecControllers controllers = new ExecControllers(command, Version.current());
             BatchingProxy proxy = controllers.batched(null, batch)) {
            int runs = Math.max(maps, batch);
            err.println("bench: the trivial controller, batch " + proxy.batch() + ": warming up (" + batch + " runs), then "
                    + runs + " runs ...");
            for (RunRecord r : BatchedRuns.run(batch, proxy, (i, f) -> {
                WorldMap map = MapGenerator.generate(WARM_UP_SEED + i);
                return new LiveRun(map, map.seed(), Set.of(), f);
            })) {
                sink += r.result().ticks();
            }
            long cpuBefore = cpuNanos();
            long start = System.nanoTime();
            long ticks = 0;
            for (RunRecord r : BatchedRuns.run(runs, proxy, (i, f) -> new LiveRun(MapGenerator.generate(i + 1), i + 1,
                    Set.of(), f))) {
                ticks += r.result().ticks();
            }
            long nanos = System.nanoTime() - start;
            long cpu = cpuNanos() - cpuBefore;
            sink += ticks;
            return new ProtocolTiming(ticks / (nanos / 1e9), cpu / 1e3 / ticks);
        } catch (ControllerStartException e) {
            throw new UsageException("bench: --protocol needs python3 on the PATH: " + e.getMessage() + ".");
        }
    }

    private static ProtocolTiming protocolTicksPerSecond(List<String> command, int maps, PrintStream err)
            throws UsageException {
        try (ExecControllers controllers = new ExecControllers(command, Version.current())) {
            try {
                controllers.check(null);
            } catch (ControllerStartException e) {
                throw new UsageException("bench: --protocol needs python3 on the PATH: " + e.getMessage() + ".");
            }
            ControllerFactory worker = controllers.worker(null);
            err.println("bench: the trivial controller " + (command.size() > 2 ? "asking for the radar and obstacles"
                    : "asking for no sensor") + ": warming up (" + PROTOCOL_WARM_UP_RUNS + " runs), then " + maps + " runs ...");
            for (int i = 0; i < PROTOCOL_WARM_UP_RUNS; i++) {
                WorldMap map = MapGenerator.generate(WARM_UP_SEED + i);
                sink += Simulator.run(map, map.seed(), Set.of(), RunObserver.NONE, worker).result().ticks();
            }
            long ticks = 0;
            long cpuBefore = cpuNanos();
            long start = System.nanoTime();
            for (long seed = 1; seed <= maps; seed++) {
                ticks += Simulator.run(MapGenerator.generate(seed), seed, Set.of(), RunObserver.NONE, worker).result().ticks();
            }
            long nanos = System.nanoTime() - start;
            long cpu = cpuNanos() - cpuBefore;
            sink += ticks;
            return new ProtocolTiming(ticks / (nanos / 1e9), cpu / 1e3 / ticks);
        }
    }

    /**
     * Round trips a second, and the CPU time a tick took in sitcov and in the controller together:
     * on a machine shared with other work the wall clock measures the others too, the CPU time much
     * less so, and 10^6 / (µs a tick) is what one core to themselves would allow.
     */
    private record ProtocolTiming(double perSecond, double cpuMicrosPerTick) {
    }

    /** CPU time so far of this JVM (every thread) and of the processes it started. */
    private static long cpuNanos() {
        long own = ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory
                .getOperatingSystemMXBean()).getProcessCpuTime();
        long children = ProcessHandle.current().descendants()
                .mapToLong(p -> p.info().totalCpuDuration().map(java.time.Duration::toNanos).orElse(0L)).sum();
        return own + children;
    }
}
