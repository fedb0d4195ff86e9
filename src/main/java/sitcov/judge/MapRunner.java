package sitcov.judge;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import sitcov.control.ControllerFactory;
import sitcov.faults.Fault;
import sitcov.oracle.RunResult;
import sitcov.seam.SeamFault;
import sitcov.vehicles.CommandLog;
import sitcov.world.WorldMap;

/**
 * The one place a map is judged: run fault-free, then once per fault (one fault at a time) with
 * the same internal seed, each faulty run judged by the {@link DifferentialOracle} against the
 * fault-free one. Experiments, fault calibration and the regression tests all come through here.
 */
public final class MapRunner {
    private MapRunner() {
    }

    /**
     * Judges every fault of {@code faults}, in the list's order, each faulty run as long as
     * {@code length} says, every run driven by the controller {@code controller} makes.
     */
    public static JudgedMap judge(WorldMap map, long internalSeed, List<Fault> faults, FaultyRuns length,
                                  ControllerFactory controller) {
        if (forks(faults, controller)) {
            return ForkedRuns.judge(map, internalSeed, faults, length, controller).judged();
        }
        RunRecord reference = Simulator.run(map, internalSeed, Set.of(), RunObserver.NONE, controller);
        RunResult faultFree = reference.result();
        List<FaultVerdict> verdicts = new ArrayList<>(faults.size());
        List<CommandLog> commands = new ArrayList<>(1 + faults.size());
        commands.add(reference.commands());
        for (Fault fault : faults) {
            RunRecord faulty = length == FaultyRuns.UNTIL_VERDICT
                    ? Simulator.runUntilVerdict(map, internalSeed, EnumSet.of(fault), faultFree, controller)
                    : Simulator.runJudged(map, internalSeed, EnumSet.of(fault), controller);
            verdicts.add(DifferentialOracle.judge(faultFree, faulty, fault));
            commands.add(faulty.commands());
        }
        return new JudgedMap(faultFree, verdicts, commands);
    }

    /**
     * Judges every variant of {@code variants}, in the list's order, against the reference runs of
     * {@code reference}: a seeded fault as above (forked where it departs when it can be), another
     * controller ({@code controllers} makes it for this thread) run whole, its effect the ticks its
     * commands differ from the reference's, a seam fault as {@link SeamRuns} judges it.
     */
    public static JudgedMap judgeVariants(WorldMap map, long internalSeed, List<Variant> variants, FaultyRuns length,
                                          ControllerFactory reference,
                                          Function<Variant.Controller, ControllerFactory> controllers) {
        List<Fault> seeded = Variant.faultsOf(variants);
        if (seeded.size() == variants.size()) {
            return judge(map, internalSeed, seeded, length, reference);
        }
        CommandTrace trace = new CommandTrace();
        List<SeamFault> seams = Variant.seamsOf(variants);
        SeamRuns seamRuns = new SeamRuns(map, internalSeed, seams, length, reference);
        RunRecord baseRun = seamRuns.reference(trace);
        RunResult base = baseRun.result();
        Map<SeamFault, Variant.Seam> seamVariants = new EnumMap<>(SeamFault.class);
        variants.stream().filter(v -> v instanceof Variant.Seam).map(v -> (Variant.Seam) v)
                .forEach(v -> seamVariants.put(v.fault(), v));
        Map<SeamFault, RunRecord> seamRecords = new EnumMap<>(SeamFault.class);
        Map<SeamFault, FaultVerdict> seamVerdicts = seams.isEmpty() ? Map.of()
                : seamRuns.verdicts(seamVariants, seamRecords);
        List<FaultVerdict> verdicts = new ArrayList<>(variants.size());
        List<CommandLog> commands = new ArrayList<>(1 + variants.size());
        commands.add(baseRun.commands());
        for (Variant v : variants) {
            VerdictWatch watch = length == FaultyRuns.UNTIL_VERDICT ? new VerdictWatch(base) : null;
            if (v instanceof Variant.Seeded s) {
                RunRecord faulty = Simulator.drive(new LiveRun(map, internalSeed, EnumSet.of(s.fault()), reference)
                        .judged(), RunObserver.NONE, watch);
                verdicts.add(DifferentialOracle.judge(base, faulty, s.fault()));
                commands.add(faulty.commands());
            } else if (v instanceof Variant.Seam s) {
                verdicts.add(seamVerdicts.get(s.fault()));
                commands.add(seamRecords.get(s.fault()).commands());
            } else if (v instanceof Variant.Controller c) {
                CommandTrace.Comparison differs = trace.comparison();
                RunRecord run = Simulator.drive(new LiveRun(map, internalSeed, Set.of(), controllers.apply(c)).judged(),
                        differs, watch);
                verdicts.add(DifferentialOracle.judge(base, run.result(), c, true, differs.differing(), differs.first()));
                commands.add(run.commands());
            }
        }
        return new JudgedMap(base, verdicts, commands);
    }

    /**
     * The ticks judging {@code map} as {@link #judge(WorldMap, long, List, FaultyRuns, ControllerFactory)}
     * does steps: every run whole, or (forked) the fault-free run, the run that feeds the checkpoints
     * and each fork from its departure on. What {@code bench} shows forking saves.
     */
    public static long ticksStepped(WorldMap map, long internalSeed, List<Fault> faults, FaultyRuns length,
                                    ControllerFactory controller) {
        return forks(faults, controller)
                ? ForkedRuns.judge(map, internalSeed, faults, length, controller).ticksStepped()
                : judge(map, internalSeed, faults, length, controller).ticks();
    }

    private static boolean forks(List<Fault> faults, ControllerFactory controller) {
        return controller.copyable() && !faults.isEmpty() && Set.copyOf(faults).size() == faults.size();
    }
}
