package sitcov.judge;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.function.IntConsumer;
import sitcov.control.ControllerFactory;
import sitcov.control.ControllerSource;
import sitcov.faults.Fault;
import sitcov.world.MapGenerator;

/**
 * Every fault of a set on maps {@code first .. first+maps-1} (internal seed = external seed): one
 * fault-free run per map and one run per fault (stopped at its verdict), judged by the {@link MapRunner}. Maps run
 * in parallel, results come back in map order, so the outcome does not depend on the thread count.
 */
public final class FaultCalibration {
    private FaultCalibration() {
    }

    /** The judged maps, in map order, every run of the controller {@code car} makes; each map's verdicts in fault id order. */
    public static List<JudgedMap> run(long first, int maps, Set<Fault> faults, int threads, ControllerFactory car,
                                      IntConsumer progress) {
        List<Fault> ordered = new ArrayList<>(faults.isEmpty() ? EnumSet.noneOf(Fault.class) : EnumSet.copyOf(faults));
        List<Callable<JudgedMap>> tasks = new ArrayList<>(maps);
        for (int i = 0; i < maps; i++) {
            long seed = first + i;
            // every column of calibration is a verdict, which a faulty run has settled when it stops
            tasks.add(() -> MapRunner.judge(MapGenerator.generate(seed), seed, ordered, FaultyRuns.UNTIL_VERDICT, car));
        }
        return InOrder.run(tasks, threads, progress, "fault calibration");
    }

    /**
     * Every variant of {@code variants} (seam faults of the reference, say) judged on the same maps,
     * each against the reference runs of the controller {@code reference} makes for the worker thread.
     */
    public static List<JudgedMap> runVariants(long first, int maps, List<Variant> variants, int threads,
                                              ControllerSource reference, IntConsumer progress) {
        List<Callable<JudgedMap>> tasks = new ArrayList<>(maps);
        for (int i = 0; i < maps; i++) {
            long seed = first + i;
            tasks.add(() -> MapRunner.judgeVariants(MapGenerator.generate(seed), seed, variants, FaultyRuns.UNTIL_VERDICT,
                    reference.forThisThread(), c -> {
                        throw new IllegalArgumentException("calibration judges versions of one controller, not " + c.spec());
                    }));
        }
        return InOrder.run(tasks, threads, progress, "fault calibration");
    }
}
