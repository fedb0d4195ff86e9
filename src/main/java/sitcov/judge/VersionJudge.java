package sitcov.judge;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.oracle.NewAccidents;
import sitcov.oracle.RunResult;
import sitcov.world.WorldMap;

/**
 * Versions compared by the differential oracle: a map run once with the reference controller and
 * once with each variant, on the same internal seed, each variant judged against the reference as a
 * faulty run is against the fault-free one (an accident is new unless the other run has the same
 * type within {@link NewAccidents#SAME_PLACE} metres).
 */
public final class VersionJudge {
    private VersionJudge() {
    }

    public static List<VersionVerdict> judge(WorldMap map, long internalSeed, ControllerFactory reference,
                                             List<ControllerFactory> variants) {
        RunResult base = Simulator.run(map, internalSeed, Set.of(), RunObserver.NONE, reference).result();
        List<VersionVerdict> verdicts = new ArrayList<>(variants.size());
        for (int v = 0; v < variants.size(); v++) {
            RunResult run = Simulator.run(map, internalSeed, Set.of(), RunObserver.NONE, variants.get(v)).result();
            verdicts.add(new VersionVerdict(v, base, run, NewAccidents.between(base, run), NewAccidents.between(run, base)));
        }
        return verdicts;
    }
}
