package sitcov.judge;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.faults.PlantedFaults;
import sitcov.oracle.NewAccidents;
import sitcov.oracle.RunResult;
import sitcov.world.WorldMap;

/**
 * Versions compared by the differential oracle: a map run once with the reference controller and
 * once with each variant, on the same internal seed, each variant judged against the reference as a
 * faulty run is against the fault-free one (an accident is new unless the other run has the same
 * type within {@link NewAccidents#SAME_PLACE} metres). Versions of a controller with faults planted
 * ({@link PlantedFaults}) are forked from the reference run where their faults first depart, with the same results.
 */
public final class VersionJudge {
    private VersionJudge() {
    }

    public static List<VersionVerdict> judge(WorldMap map, long internalSeed, ControllerFactory reference,
                                             List<ControllerFactory> variants) {
        List<RunResult> runs = forkable(reference, variants)
                ? ForkedRuns.versions(map, internalSeed, variants.stream().map(v -> ((PlantedFaults) v).planted()).toList(),
                        reference)
                : whole(map, internalSeed, reference, variants);
        RunResult base = runs.get(0);
        List<VersionVerdict> verdicts = new ArrayList<>(variants.size());
        for (int v = 0; v < variants.size(); v++) {
            RunResult run = runs.get(v + 1);
            verdicts.add(new VersionVerdict(v, base, run, NewAccidents.between(base, run), NewAccidents.between(run, base)));
        }
        return verdicts;
    }

    /**
     * A controller against versions of it with faults planted: each version is a faulty run of the
     * reference, so it is forked from the reference run where its faults first depart.
     */
    private static boolean forkable(ControllerFactory reference, List<ControllerFactory> variants) {
        return reference.copyable() && variants.stream()
                .allMatch(v -> v instanceof PlantedFaults planted && planted.reference() == reference);
    }

    private static List<RunResult> whole(WorldMap map, long internalSeed, ControllerFactory reference,
                                         List<ControllerFactory> variants) {
        List<RunResult> runs = new ArrayList<>(variants.size() + 1);
        runs.add(Simulator.run(map, internalSeed, Set.of(), RunObserver.NONE, reference).result());
        for (ControllerFactory variant : variants) {
            runs.add(Simulator.run(map, internalSeed, Set.of(), RunObserver.NONE, variant).result());
        }
        return runs;
    }
}
