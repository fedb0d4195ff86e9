package sitcov.export;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import sitcov.control.ControllerFactory;
import sitcov.control.Vehicle;
import sitcov.faults.Fault;
import sitcov.judge.RunObserver;
import sitcov.judge.Simulator;
import sitcov.oracle.AccidentDetector;
import sitcov.oracle.ExcusedContact;
import sitcov.oracle.RunResult;
import sitcov.vehicles.CommandLog;
import sitcov.vehicles.Telemetry;
import sitcov.world.Dimensions;
import sitcov.world.StartPose;
import sitcov.world.WorldMap;

/**
 * One run of the builtin car, every vehicle's pose at every tick: what a player needs to replay
 * exactly what happened. A track's sample 0 is the start (time 0 s); sample {@code t + 1} is the
 * state after tick {@code t}. Parked cars never move, so the map holds them.
 *
 * @param result   the whole run's result, even where the recording stops before its end
 * @param tracks   the car under test first, then every moving car in the order of the map's moving cars
 * @param excused  the contacts of the car under test the blame rules excused, to the end of the recording
 * @param traffic  the contacts between two other vehicles, which the oracle does not judge, to the end of the
 *                 recording
 */
public record RunRecording(WorldMap map, long internalSeed, Set<Fault> faults, RunResult result, List<Track> tracks,
                           List<ExcusedContact> excused, List<Touch> traffic) {
    public RunRecording {
        faults = Set.copyOf(faults);
        tracks = List.copyOf(tracks);
        excused = List.copyOf(excused);
        traffic = List.copyOf(traffic);
    }

    /**
     * The same run recorded only to the end of {@code lastTick}: a failing run need not be played
     * long after its failure (a car that crashed early may stand for thousands of ticks).
     */
    public RunRecording until(long lastTick) {
        int all = tracks.get(0).samples().size();
        // lastTick may be Long.MAX_VALUE, "to the end": capped before adding, so that it cannot overflow
        int samples = (int) Math.min(all, Math.min(lastTick, all) + 2);
        List<Track> cut = tracks.stream().map(t -> new Track(t.entity(), t.sitcovId(),
                t.samples().subList(0, samples))).toList();
        return new RunRecording(map, internalSeed, faults, result, cut,
                excused.stream().filter(c -> c.tick() <= lastTick).toList(),
                traffic.stream().filter(c -> c.tick() <= lastTick).toList());
    }

    /**
     * The same run cut {@code after} ticks after the car under test stopped for good, where that comes before the
     * recording's end: a car that stands until its timeout would otherwise cost a player the rest of the 1000 s of
     * traffic around it, which shows nothing more of why it stopped.
     */
    public RunRecording cutAfterStandingFor(long after) {
        List<Sample> ego = tracks.get(0).samples();
        Sample end = ego.get(ego.size() - 1);
        int still = ego.size() - 1;
        while (still > 0 && ego.get(still - 1).equals(end)) {
            still--;
        }
        // sample k is the state after tick k - 1: the car last moved in tick still - 1
        long cut = still - 1 + after;
        return cut < lastTick() ? until(cut) : this;
    }

    /** The last tick recorded. */
    public long lastTick() {
        return tracks.get(0).samples().size() - 2;
    }

    /** Whether the recording stops before the run ended. */
    public boolean isCut() {
        return lastTick() + 1 < result.ticks();
    }

    /** The run's accidents up to the end of the recording. */
    public List<sitcov.oracle.Accident> accidents() {
        return result.accidents().stream().filter(a -> a.tick() <= lastTick()).toList();
    }

    /** Two vehicles other than the car under test whose footprints came to touch at the end of {@code tick}. */
    public record Touch(long tick, String entity, String other) {
    }

    /** A vehicle's front-centre pose (as sitcov anchors vehicles) and whether it was on the map. */
    public record Sample(double x, double y, double bearing, boolean active) {
    }

    /**
     * One vehicle's poses, tick by tick.
     *
     * @param sitcovId the vehicle's id in the run (the car under test is 0), as accidents name their other party
     */
    public record Track(String entity, int sitcovId, List<Sample> samples) {
        public Track {
            samples = List.copyOf(samples);
        }
    }

    /** The name the car under test has in an exported scenario. */
    public static final String EGO = "ego";

    /** Runs {@code controller}'s car with {@code faults} on {@code map} to its end, recording every vehicle. */
    public static RunRecording of(WorldMap map, long internalSeed, Set<Fault> faults, ControllerFactory controller) {
        Recorder recorder = new Recorder(map);
        return of(map, internalSeed, faults, Simulator.run(map, internalSeed, faults, recorder, controller).result(),
                recorder);
    }

    /**
     * A run replayed from the commands it carried out ({@code commands}), whatever controller made them,
     * stopped after {@code stopAfter} ticks where the experiment stopped it ({@link Simulator#replay});
     * {@code faults} are the seeded faults its controller had on, named in the export.
     */
    public static RunRecording replayed(WorldMap map, long internalSeed, CommandLog commands, long stopAfter,
                                        Set<Fault> faults) {
        Recorder recorder = new Recorder(map);
        return of(map, internalSeed, faults, Simulator.replay(map, internalSeed, commands, stopAfter, recorder).result(),
                recorder);
    }

    private static RunRecording of(WorldMap map, long internalSeed, Set<Fault> faults, RunResult result, Recorder recorder) {
        List<Track> tracks = new ArrayList<>();
        for (int i = 0; i < recorder.samples.size(); i++) {
            tracks.add(new Track(i == 0 ? EGO : movingName(i - 1), recorder.ids[i], recorder.samples.get(i)));
        }
        return new RunRecording(map, internalSeed, faults, result, tracks, recorder.excused, recorder.traffic);
    }

    /** The name of the moving car at {@code index} of the map's moving cars. */
    static String movingName(int index) {
        return "moving" + index;
    }

    static String parkedName(int id) {
        return "parked" + id;
    }

    /** Collects the samples, the contacts and, from the ticks, each vehicle's id. */
    private static final class Recorder implements RunObserver {
        private final List<List<Sample>> samples = new ArrayList<>();
        private final int[] ids;
        private final TrafficContacts contacts;
        private final List<Touch> traffic = new ArrayList<>();
        private List<ExcusedContact> excused = List.of();

        Recorder(WorldMap map) {
            StartPose car = map.layout().carStart().orElseThrow(() ->
                    new IllegalArgumentException("map " + map.seed() + " has no start for the car, so no run"));
            int vehicles = 1 + map.movingCars().size();
            ids = new int[vehicles];
            samples.add(new ArrayList<>(List.of(start(car))));
            for (StartPose p : map.movingCars()) {
                samples.add(new ArrayList<>(List.of(start(p))));
            }
            contacts = new TrafficContacts(map.movingCars().size(), map.layout().parkedCars().size());
        }

        private static Sample start(StartPose p) {
            return new Sample(p.position().x(), p.position().y(), p.heading().bearing(), true);
        }

        @Override
        public void afterTick(long tick, Telemetry run, AccidentDetector detector) {
            keep(0, run.car());
            List<? extends Vehicle> moving = run.movingCars();
            for (int i = 0; i < moving.size(); i++) {
                keep(i + 1, moving.get(i));
            }
            contacts.step(tick, moving, run.parkedBodies(), traffic);
            excused = detector.excusedContactEvents();
        }

        private void keep(int track, Vehicle v) {
            ids[track] = v.id();
            samples.get(track).add(new Sample(v.x(), v.y(), v.heading(), v.isActive()));
        }
    }

    /** How long the recorded run lasted. */
    double seconds() {
        return (tracks.get(0).samples().size() - 1) * Dimensions.TICK_SECONDS;
    }
}
