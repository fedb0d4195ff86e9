package sitcov.experiment;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.function.IntConsumer;
import sitcov.faults.Fault;
import sitcov.oracle.RunResult;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * Every fault of a set on maps {@code first .. first+maps-1} (internal seed = external seed): one
 * fault-free run per map and one run per fault, judged by the {@link DifferentialOracle}. Maps run
 * in parallel, results come back in map order, so the outcome does not depend on the thread count.
 */
public final class FaultCalibration {
    private FaultCalibration() {
    }

    /** The verdicts of one map, in fault id order, beside its fault-free run. */
    public record MapVerdicts(RunResult faultFree, List<FaultVerdict> verdicts) {
    }

    public static List<MapVerdicts> run(long first, int maps, Set<Fault> faults, int threads, IntConsumer progress) {
        List<Fault> ordered = new ArrayList<>(faults.isEmpty() ? EnumSet.noneOf(Fault.class) : EnumSet.copyOf(faults));
        List<Callable<MapVerdicts>> tasks = new ArrayList<>(maps);
        for (int i = 0; i < maps; i++) {
            long seed = first + i;
            tasks.add(() -> judgeMap(MapGenerator.generate(seed), seed, ordered));
        }
        return InOrder.run(tasks, threads, progress, "fault calibration");
    }

    static MapVerdicts judgeMap(WorldMap map, long internalSeed, List<Fault> faults) {
        RunResult faultFree = Simulator.run(map, internalSeed);
        List<FaultVerdict> verdicts = new ArrayList<>(faults.size());
        for (Fault fault : faults) {
            RunRecord faulty = Simulator.run(map, internalSeed, EnumSet.of(fault), RunObserver.NONE);
            verdicts.add(DifferentialOracle.judge(faultFree, faulty, fault));
        }
        return new MapVerdicts(faultFree, verdicts);
    }
}
