package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.world.MapGenerator;

class KeptVerticesTest {

    @Test
    void aCarDrivingStraightAtASteadySpeedNeedsOnlyItsTwoEnds() {
        List<RunRecording.Sample> samples = new ArrayList<>();
        for (int i = 0; i < 50; i++) {
            samples.add(new RunRecording.Sample(10 + 2.5 * i, 40, 90, true));
        }
        assertEquals(List.of(0, 49), KeptVertices.of(samples));
    }

    @Test
    void aCarSpeedingUpKeepsItsVerticesBecauseInterpolationWouldPutItAheadOfItself() {
        List<RunRecording.Sample> samples = new ArrayList<>();
        double x = 0;
        for (int i = 0; i < 10; i++) {
            x += 0.1 * i; // speed grows 0.1 m a tick: halfway between two ticks the car is 5 cm behind the chord
            samples.add(new RunRecording.Sample(x, 40, 90, true));
        }
        assertEquals(10, KeptVertices.of(samples).size());
    }

    @Test
    void aCarThatLeavesTheMapKeepsTheSamplesEitherSideOfItsAbsence() {
        List<RunRecording.Sample> samples = List.of(
                new RunRecording.Sample(0, 0, 90, true), new RunRecording.Sample(1, 0, 90, true),
                new RunRecording.Sample(2, 0, 90, false), new RunRecording.Sample(3, 0, 90, true),
                new RunRecording.Sample(4, 0, 90, true));
        assertEquals(List.of(0, 1, 2, 3, 4), KeptVertices.of(samples));
    }

    @Test
    void everyRecordedPoseOfARealRunIsWithinAMillimetreOfTheInterpolationBetweenKeptVertices() {
        RunRecording run = RunRecording.of(MapGenerator.generate(21), 21, Set.of(), BuiltinCar.FACTORY);
        int dropped = 0;
        for (RunRecording.Track track : run.tracks()) {
            List<RunRecording.Sample> samples = track.samples();
            List<Integer> kept = KeptVertices.of(samples);
            assertEquals(0, kept.get(0));
            assertEquals(samples.size() - 1, kept.get(kept.size() - 1));
            for (int k = 0; k + 1 < kept.size(); k++) {
                RunRecording.Sample a = samples.get(kept.get(k));
                RunRecording.Sample b = samples.get(kept.get(k + 1));
                for (int i = kept.get(k) + 1; i < kept.get(k + 1); i++) {
                    double f = (double) (i - kept.get(k)) / (kept.get(k + 1) - kept.get(k));
                    RunRecording.Sample s = samples.get(i);
                    double error = Math.hypot(s.x() - (a.x() + (b.x() - a.x()) * f), s.y() - (a.y() + (b.y() - a.y()) * f));
                    assertTrue(error <= 0.001, track.entity() + " sample " + i + " is " + error + " m off");
                    dropped++;
                }
            }
        }
        assertTrue(dropped > 0, "a run of map 21 has stretches of steady motion to leave out");
    }
}
