package sitcov.judge;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.faults.Shadow;
import sitcov.oracle.RunResult;
import sitcov.vehicles.CommandLog;
import sitcov.world.WorldMap;

/**
 * Judges a map without re-running what a fault does not change. The fault-free run watches every
 * fault from the shadows; a fault that never departs from it is judged from it (its faulty run
 * would be the same run), and every other faulty run starts from a checkpoint of the fault-free run
 * at the start of the tick its fault departs, taken from a second fault-free run stepped forward
 * from one departure to the next. The verdicts are those of whole runs, byte for byte: a faulty run
 * is the fault-free run tick for tick until its fault departs.
 */
final class ForkedRuns {
    private ForkedRuns() {
    }

    /** A map judged, and the ticks judging it stepped: the watching run's, the feeder's and the forks'. */
    record Judging(JudgedMap judged, long ticksStepped) {
    }

    static Judging judge(WorldMap map, long internalSeed, List<Fault> faults, FaultyRuns length,
                         ControllerFactory controller) {
        LiveRun watching = LiveRun.watching(map, internalSeed, EnumSet.copyOf(faults), controller);
        RunRecord reference = Simulator.drive(watching, RunObserver.NONE, null);
        RunResult faultFree = reference.result();
        long stepped = faultFree.ticks();
        FaultVerdict[] verdicts = new FaultVerdict[faults.size()];
        CommandLog[] commands = new CommandLog[1 + faults.size()];
        commands[0] = reference.commands();
        List<Integer> departing = new ArrayList<>();
        for (int i = 0; i < faults.size(); i++) {
            Shadow shadow = watching.shadow(faults.get(i));
            if (shadow.departs()) {
                departing.add(i);
            } else {
                verdicts[i] = DifferentialOracle.judge(faultFree, unchanged(reference, shadow), shadow.fault());
                commands[1 + i] = reference.commands();
            }
        }
        departing.sort(Comparator.comparingLong(i -> watching.shadow(faults.get(i)).departureTick()));
        Feeder feeder = new Feeder(map, internalSeed, controller);
        for (int i : departing) {
            Shadow shadow = watching.shadow(faults.get(i));
            long departs = shadow.departureTick();
            LiveRun faulty = feeder.at(departs).forkWith(shadow.fault(), shadow.reachedBefore(departs)).judged();
            VerdictWatch watch = length == FaultyRuns.UNTIL_VERDICT ? new VerdictWatch(faultFree) : null;
            RunRecord run = Simulator.drive(faulty, RunObserver.NONE, watch);
            stepped += run.result().ticks() - departs;
            verdicts[i] = DifferentialOracle.judge(faultFree, run, shadow.fault());
            commands[1 + i] = run.commands();
        }
        stepped += feeder.ticks();
        return new Judging(new JudgedMap(faultFree, List.of(verdicts), List.of(commands)), stepped);
    }

    /** The record of a faulty run that never departed from the fault-free run: that run, and what the fault did in it. */
    private static RunRecord unchanged(RunRecord faultFree, Shadow shadow) {
        List<Activation> activations = new ArrayList<>(Fault.values().length);
        for (Fault f : Fault.values()) {
            activations.add(f == shadow.fault() ? shadow.activation() : new Activation(f, false, false, 0, -1));
        }
        return new RunRecord(faultFree.result(), Set.of(shadow.fault()), activations, faultFree.commands());
    }

    /** The fault-free run the checkpoints come from, made when first asked for and stepped on to each departure in turn. */
    private static final class Feeder {
        private final WorldMap map;
        private final long internalSeed;
        private final ControllerFactory controller;
        private LiveRun run;

        Feeder(WorldMap map, long internalSeed, ControllerFactory controller) {
            this.map = map;
            this.internalSeed = internalSeed;
            this.controller = controller;
        }

        /** The run at the start of tick {@code departs}; departures must come in order. */
        LiveRun at(long departs) {
            if (run == null) {
                run = new LiveRun(map, internalSeed, Set.of(), controller);
            }
            while (run.tick() < departs - 1) {
                run.step();
            }
            return run;
        }

        /** The ticks stepped so far. */
        long ticks() {
            return run == null ? 0 : run.tick() + 1;
        }
    }
}
