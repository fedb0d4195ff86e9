package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Element;
import sitcov.builtin.BuiltinCar;
import sitcov.faults.Fault;
import sitcov.geom.Vec2;
import sitcov.oracle.Outcome;
import sitcov.vehicles.AutonomousCar;
import sitcov.vehicles.MovingCar;
import sitcov.world.MapGenerator;

class KeptVerticesTest {
    /** A run that times out with fault 17, 5000 ticks of 19 moving cars that stop, start, turn and leave the map. */
    private static final long TIMEOUT_MAP = 570240261368197319L;
    private static final long TIMEOUT_INTERNAL = 7262292177969351214L;
    private static final double TICK_SECONDS = 0.2;

    @Test
    void aCarDrivingStraightAtASteadySpeedNeedsOnlyItsTwoEnds() {
        List<RunRecording.Sample> samples = new ArrayList<>();
        for (int i = 0; i < 50; i++) {
            samples.add(new RunRecording.Sample(10 + 2.5 * i, 40, 90, true));
        }
        assertEquals(List.of(0, 49), kept(samples));
    }

    @Test
    void aCarSpeedingUpKeepsItsVerticesBecauseInterpolationWouldPutItAheadOfItself() {
        List<RunRecording.Sample> samples = new ArrayList<>();
        double x = 0;
        for (int i = 0; i < 10; i++) {
            x += 0.1 * i; // speed grows 0.1 m a tick: halfway between two ticks the car is 5 cm behind the chord
            samples.add(new RunRecording.Sample(x, 40, 90, true));
        }
        assertEquals(10, kept(samples).size());
    }

    @Test
    void aCarThatLeavesTheMapKeepsTheSamplesEitherSideOfItsAbsence() {
        List<RunRecording.Sample> samples = List.of(
                new RunRecording.Sample(0, 0, 90, true), new RunRecording.Sample(1, 0, 90, true),
                new RunRecording.Sample(2, 0, 90, false), new RunRecording.Sample(3, 0, 90, true),
                new RunRecording.Sample(4, 0, 90, true));
        assertEquals(List.of(0, 1, 2, 3, 4), kept(samples));
    }

    @Test
    void aVertexIsWrittenInWholeMillimetresOfItsRearAxleAndAHeadingWestStaysInsideMinusPiToPi() {
        // a moving car heading west (bearing 270) with its front at (50.0004, 30): its rear axle 3.5 m east of it
        KeptVertices.Vertex v = KeptVertices.of(List.of(new RunRecording.Sample(50.0004, 30, 270, true)),
                ScenarioParts.Kind.MOVING).get(0);
        assertEquals(53500, v.x(), "x 53.5004 m to the millimetre");
        assertEquals(70000, v.y(), "y = 100 − 30");
        // π is 3.14159…: rounded to four decimals it would be 3.1416, beyond π
        assertEquals(31415, v.h());
    }

    @Test
    void aTimedOutRunPlayedBetweenItsWrittenVerticesKeepsEveryRearAxleAndFrontWithinAMillimetreAndEveryHeadingWithinTheTolerance() {
        RunRecording run = RunRecording.of(MapGenerator.generate(TIMEOUT_MAP), TIMEOUT_INTERNAL,
                Set.of(Fault.ofId(17)), BuiltinCar.FACTORY);
        assertEquals(Outcome.TIMEOUT, run.result().outcome(), "the run no longer times out: pick another that does");
        Element root = Dom.parse(OpenScenario.recording(run, "map.xodr", ScenarioVersion.V1_0));
        int samples = 0;
        int vertices = 0;
        int standing = 0;
        int away = 0;
        double worstMetres = 0;
        double worstDegrees = 0;
        for (RunRecording.Track track : run.tracks()) {
            List<double[]> written = writtenVertices(root, track.entity());
            vertices += written.size();
            double rearAxle = track.entity().equals(RunRecording.EGO) ? AutonomousCar.REAR_AXLE : MovingCar.REAR_AXLE;
            List<RunRecording.Sample> s = track.samples();
            int[] from = {0};
            for (int k = 0; k < s.size(); k++) {
                RunRecording.Sample sample = s.get(k);
                if (!sample.active()) {
                    away++;
                    continue;
                }
                standing += k > 0 && s.get(k - 1).equals(sample) ? 1 : 0;
                // the rear axle, reckoned here from sitcov's front centre and bearing
                double heading = Frame.heading(sample.bearing());
                Vec2 expected = Frame.point(sample.x(), sample.y()).minus(Frame.unit(heading).times(rearAxle));
                double[] played = interpolated(written, k * TICK_SECONDS, track.entity(), from, rearAxle);
                worstMetres = Math.max(worstMetres, expected.distanceTo(new Vec2(played[0], played[1])));
                // the front too, as a player that interpolates another point of the car would place it
                worstMetres = Math.max(worstMetres, Frame.point(sample.x(), sample.y()).distanceTo(new Vec2(played[3], played[4])));
                worstDegrees = Math.max(worstDegrees, Math.toDegrees(Frame.angleBetween(played[2], heading)));
                samples++;
            }
        }
        assertTrue(standing > 1000 && away > 0, "the run has standing cars (" + standing + " samples) and cars away from the"
                + " map (" + away + "): pick another that has both");
        // reckoned here another way, the same rear axle may differ in its last bits: a nanometre is allowed for that
        assertTrue(worstMetres <= KeptVertices.POSITION_TOLERANCE + 1e-9, "a rear axle or a front is played " + worstMetres + " m off");
        assertTrue(worstDegrees <= KeptVertices.HEADING_TOLERANCE_DEGREES + 1e-9, "a heading is played " + worstDegrees + "° off");
        // a car standing costs a vertex where it stops and one where it sets off: most of its samples are left out
        assertTrue(vertices < samples - standing / 2, vertices + " vertices for " + samples + " samples on the map, "
                + standing + " of them standing");
    }

    private static List<Integer> kept(List<RunRecording.Sample> samples) {
        return KeptVertices.of(samples, ScenarioParts.Kind.MOVING).stream().map(KeptVertices.Vertex::sample).toList();
    }

    /** Every vertex of the entity's trajectories as {time, x, y, h}, in order of time. */
    private static List<double[]> writtenVertices(Element root, String entity) {
        List<double[]> out = new ArrayList<>();
        for (Element group : Dom.descendants(root, "ManeuverGroup")) {
            if (Dom.text(group, "name").equals(entity)) {
                for (Element v : Dom.descendants(group, "Vertex")) {
                    Element p = Dom.child(Dom.child(v, "Position"), "WorldPosition");
                    out.add(new double[] {Dom.number(v, "time"), Dom.number(p, "x"), Dom.number(p, "y"), Dom.number(p, "h")});
                }
            }
        }
        return out;
    }

    /**
     * {x, y, h, front x, front y} at {@code t}, each linear between the vertices either side (the heading the
     * shorter way round; a vertex's front {@code rearAxle} ahead of it); {@code from[0]} is where to start looking,
     * moved on as the times asked for grow.
     */
    private static double[] interpolated(List<double[]> vertices, double t, String entity, int[] from, double rearAxle) {
        for (int i = from[0]; i < vertices.size(); i++) {
            double[] b = vertices.get(i);
            if (Math.abs(b[0] - t) < 1e-9) {
                from[0] = i;
                return between(b, b, 0, rearAxle);
            }
            if (b[0] > t && i > 0 && vertices.get(i - 1)[0] < t) {
                from[0] = i - 1;
                double[] a = vertices.get(i - 1);
                return between(a, b, (t - a[0]) / (b[0] - a[0]), rearAxle);
            }
        }
        throw new AssertionError(entity + " has no vertices either side of " + t + " s");
    }

    private static double[] between(double[] a, double[] b, double f, double rearAxle) {
        double[] frontA = {a[1] + Math.cos(a[3]) * rearAxle, a[2] + Math.sin(a[3]) * rearAxle};
        double[] frontB = {b[1] + Math.cos(b[3]) * rearAxle, b[2] + Math.sin(b[3]) * rearAxle};
        return new double[] {a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]),
                a[3] + f * Math.IEEEremainder(b[3] - a[3], 2 * Math.PI),
                frontA[0] + f * (frontB[0] - frontA[0]), frontA[1] + f * (frontB[1] - frontA[1])};
    }
}
