package sitcov.judge;

import java.util.Comparator;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.oracle.RunResult;
import sitcov.seam.SeamActivation;
import sitcov.seam.SeamBoard;
import sitcov.seam.SeamControllers;
import sitcov.seam.SeamFault;
import sitcov.seam.SeamShadow;
import sitcov.world.WorldMap;

/**
 * Judges a map's seam faults against the reference. Where the reference's controller can be copied,
 * the reference run watches every seam fault from the shadows; a fault that never departs from it is
 * judged from it, and every other faulty run starts from a checkpoint, at the start of the tick its
 * fault departs, of a second watching run stepped from one departure to the next. Otherwise each
 * faulty run is run whole. Both ways give the same verdicts, byte for byte.
 */
final class SeamRuns {
    private final WorldMap map;
    private final long internalSeed;
    private final List<SeamFault> faults;
    private final FaultyRuns length;
    private final ControllerFactory reference;
    private final boolean forks;
    private SeamBoard watched;
    private RunRecord baseRun;
    private RunResult base;

    SeamRuns(WorldMap map, long internalSeed, List<SeamFault> faults, FaultyRuns length, ControllerFactory reference) {
        this.map = map;
        this.internalSeed = internalSeed;
        this.faults = faults;
        this.length = length;
        this.reference = reference;
        this.forks = reference.copyable() && !faults.isEmpty();
    }

    /** The reference run, watched by {@code observer}: it watches the seam faults from the shadows when they fork. */
    RunRecord reference(RunObserver observer) {
        if (!forks) {
            baseRun = Simulator.run(map, internalSeed, Set.of(), observer, reference);
        } else {
            LiveRun watching = new LiveRun(map, internalSeed, Set.of(), SeamControllers.watching(faults, reference));
            baseRun = Simulator.drive(watching, observer, null);
            watched = SeamControllers.board(watching.scene().autonomousCar().controller());
        }
        base = baseRun.result();
        return baseRun;
    }

    /**
     * The verdict on every seam fault, each against the reference run {@link #reference} ran; each
     * faulty run's record goes into {@code runs} (the reference's, for a fault that never departs).
     */
    Map<SeamFault, FaultVerdict> verdicts(Map<SeamFault, Variant.Seam> variants, Map<SeamFault, RunRecord> runs) {
        Map<SeamFault, FaultVerdict> verdicts = new EnumMap<>(SeamFault.class);
        if (!forks) {
            for (SeamFault f : faults) {
                LiveRun faulty = new LiveRun(map, internalSeed, Set.of(), SeamControllers.switchedOn(f, reference));
                verdicts.put(f, judged(faulty, variants.get(f), runs));
            }
            return verdicts;
        }
        ForkFeeder feeder = new ForkFeeder();
        List<SeamShadow> shadows = faults.stream().map(watched::shadow)
                .sorted(Comparator.comparingLong(SeamShadow::departureTick)).toList();
        for (SeamShadow shadow : shadows) {
            Variant.Seam v = variants.get(shadow.fault());
            if (!shadow.departs()) {
                verdicts.put(shadow.fault(), DifferentialOracle.judge(base, base, v, shadow.reached(), 0, -1));
                runs.put(shadow.fault(), baseRun);
                continue;
            }
            LiveRun fork = feeder.at(shadow.departureTick()).copy();
            SeamControllers.board(fork.scene().autonomousCar().controller())
                    .forkWith(shadow.fault(), shadow.reachedBefore(shadow.departureTick()));
            verdicts.put(shadow.fault(), judged(fork, v, runs));
        }
        return verdicts;
    }

    private FaultVerdict judged(LiveRun faulty, Variant.Seam v, Map<SeamFault, RunRecord> runs) {
        VerdictWatch watch = length == FaultyRuns.UNTIL_VERDICT ? new VerdictWatch(base) : null;
        RunRecord record = Simulator.drive(faulty, RunObserver.NONE, watch);
        runs.put(v.fault(), record);
        RunResult run = record.result();
        SeamActivation a = SeamControllers.board(faulty.scene().autonomousCar().controller()).activation(v.fault());
        return DifferentialOracle.judge(base, run, v, a.reached(), a.effectiveCount(), a.firstEffectiveTick());
    }

    /** The watching run the checkpoints come from, stepped on to each departure in turn. */
    private final class ForkFeeder {
        private LiveRun run;

        /** The run at the start of tick {@code departs}; departures must come in order. */
        LiveRun at(long departs) {
            if (run == null) {
                run = new LiveRun(map, internalSeed, Set.of(), SeamControllers.watching(faults, reference));
            }
            while (run.tick() < departs - 1) {
                run.step();
            }
            return run;
        }
    }
}
