package sitcov.seam;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.control.Channel;
import sitcov.control.Command;
import sitcov.control.Controller;
import sitcov.control.ControllerFactory;
import sitcov.control.Observation;
import sitcov.control.Vehicle;
import sitcov.geom.Box;
import sitcov.judge.LiveRun;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class SeamControllersTest {
    private static final long SEED = 3;

    /** The parts of the observation each fault says it changes; the command's faults change none. */
    private static final Map<SeamFault, Set<String>> CHANGES = new EnumMap<>(Map.ofEntries(
            Map.entry(SeamFault.RADAR_DROPOUT, Set.of("traffic")),
            Map.entry(SeamFault.RADAR_HALF_RANGE, Set.of("traffic")),
            Map.entry(SeamFault.PARKED_CARS_BEYOND_15M, Set.of("obstacles")),
            Map.entry(SeamFault.CAMERA_BLIND_RIGHT, Set.of("camera")),
            Map.entry(SeamFault.LIDAR_HALF_RANGE, Set.of("lidar")),
            Map.entry(SeamFault.FROZEN_FRAME, Set.of("pose", "traffic", "obstacles", "signals", "camera", "lidar", "channels")),
            Map.entry(SeamFault.LATE_FRAME, Set.of("pose", "traffic", "obstacles", "signals", "camera", "lidar", "channels")),
            Map.entry(SeamFault.POSE_NOISE, Set.of("pose")),
            Map.entry(SeamFault.LANE_OFFSET_BIAS, Set.of("channels")),
            Map.entry(SeamFault.RIGHT_OF_WAY_STUCK, Set.of("signals")),
            Map.entry(SeamFault.STEERING_BIAS, Set.of()),
            Map.entry(SeamFault.STEERING_STUCK, Set.of()),
            Map.entry(SeamFault.HALF_BRAKING, Set.of()),
            Map.entry(SeamFault.LATE_COMMAND, Set.of())));

    @Test
    void aSeamFaultChangesOnlyWhatItSaysFromItsDepartureTickAndNothingBefore() {
        WorldMap map = MapGenerator.generate(SEED);
        List<Tick> reference = run(map, f -> f);
        SeamBoard watched = watching(map);
        int departed = 0;
        for (SeamFault fault : SeamFault.values()) {
            long departs = watched.shadow(fault).departureTick();
            List<Tick> faulty = run(map, f -> SeamControllers.switchedOn(fault, f));
            int same = (int) (departs < 0 ? Math.min(reference.size(), faulty.size()) : departs);
            assertEquals(reference.subList(0, same), faulty.subList(0, same), fault + " before tick " + departs);
            if (departs < 0) {
                assertEquals(reference, faulty, fault + " never departs, so its run is the reference's");
                continue;
            }
            departed++;
            Tick r = reference.get((int) departs);
            Tick f = faulty.get((int) departs);
            List<String> differing = new ArrayList<>();
            r.parts().forEach((part, value) -> {
                if (!value.equals(f.parts().get(part))) {
                    differing.add(part);
                }
            });
            assertTrue(!differing.isEmpty() || !r.applied().equals(f.applied()), fault + " departs at " + departs);
            assertTrue(CHANGES.get(fault).containsAll(differing), fault + " changed " + differing);
            if (CHANGES.get(fault).isEmpty()) {
                assertTrue(!r.applied().equals(f.applied()), fault + " changes the command the world carries out");
            }
        }
        assertTrue(departed >= 12, "the controller here reads every part, so nearly every fault departs: " + departed);
    }

    @Test
    void theReferenceDrawsNothingFromTheFaultsStreamsAndIsUnchangedWhileWatched() {
        WorldMap map = MapGenerator.generate(SEED);
        assertEquals(run(map, f -> f), run(map, f -> SeamControllers.watching(List.of(SeamFault.values()), f)));
    }

    /** The board of a run that watches every seam fault from the shadows: when each would first change a value. */
    private static SeamBoard watching(WorldMap map) {
        LiveRun run = new LiveRun(map, SEED, Set.of(),
                SeamControllers.watching(List.of(SeamFault.values()), reading(new ArrayList<>())));
        while (run.step()) {
            // to the end
        }
        return SeamControllers.board(run.scene().autonomousCar().controller());
    }

    private static List<Tick> run(WorldMap map, java.util.function.UnaryOperator<ControllerFactory> wrap) {
        List<Tick> ticks = new ArrayList<>();
        LiveRun run = new LiveRun(map, SEED, Set.of(), wrap.apply(reading(ticks)));
        while (run.step()) {
            ticks.get(ticks.size() - 1).applied().append(run.telemetry().speedChange()).append(' ')
                    .append(run.telemetry().steering());
        }
        return ticks;
    }

    /** What the controller received in one tick, part by part, and what the world carried out. */
    record Tick(Map<String, String> parts, StringBuilder applied) {
        @Override
        public boolean equals(Object o) {
            return o instanceof Tick t && parts.equals(t.parts) && applied.toString().equals(t.applied.toString());
        }

        @Override
        public int hashCode() {
            return parts.hashCode();
        }
    }

    /** The builtin car, reading every part of every observation first (as a controller program asking for all would). */
    private static ControllerFactory reading(List<Tick> into) {
        return run -> {
            Controller car = BuiltinCar.FACTORY.start(run);
            return (Observation now, Command out) -> {
                into.add(new Tick(everything(now), new StringBuilder()));
                car.step(now, out);
            };
        };
    }

    private static Map<String, String> everything(Observation o) {
        Map<String, String> parts = new java.util.TreeMap<>();
        parts.put("pose", o.x() + " " + o.y() + " " + o.heading() + " " + o.speed());
        StringBuilder t = new StringBuilder();
        for (Vehicle v : o.traffic()) {
            t.append(v.id()).append(' ').append(v.x()).append(' ').append(v.y()).append(' ').append(v.heading()).append(';');
        }
        parts.put("traffic", t.toString());
        StringBuilder b = new StringBuilder();
        for (Box box : o.obstacles()) {
            b.append(box.centreX()).append(' ').append(box.centreY()).append(';');
        }
        parts.put("obstacles", b.toString());
        StringBuilder s = new StringBuilder();
        for (int j = 0; j < o.roads().junctions().size(); j++) {
            s.append(o.rightOfWay().holds(j)).append(o.rightOfWay().wouldGrant(j)).append(';');
        }
        parts.put("signals", s.toString());
        StringBuilder c = new StringBuilder();
        for (int h = 0; h < o.cameraHits(); h++) {
            c.append(o.cameraHitX(h)).append(' ').append(o.cameraHitY(h)).append(';');
        }
        parts.put("camera", c.toString());
        StringBuilder l = new StringBuilder();
        for (int h = 0; h < o.lidarHits(); h++) {
            l.append(o.lidarHitX(h)).append(' ').append(o.lidarHitY(h)).append(';');
        }
        parts.put("lidar", l.toString());
        StringBuilder ch = new StringBuilder();
        for (Channel channel : Channel.values()) {
            ch.append(o.channel(channel)).append(';');
        }
        parts.put("channels", ch.toString());
        return parts;
    }
}
