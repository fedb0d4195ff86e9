package sitcov.estimate;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.oracle.Failure;
import sitcov.world.DrawSite;
import sitcov.world.DrawTrace;
import sitcov.world.Tilt;

class CrossEntropyTest {
    private static Sample withMovingBin(int bin, double score) {
        int[][] bins = new int[DrawSite.values().length][];
        for (DrawSite s : DrawSite.values()) {
            bins[s.ordinal()] = new int[s.bins()];
        }
        bins[DrawSite.MOVING_CARS.ordinal()][bin] = 1;
        return new Sample(0, "ce-1", 0, 0, new DrawTrace(0, 0, bins), 10, score,
                score < 0 ? Set.of(Failure.CLASHWITHOTHERCAR) : Set.of());
    }

    @Test
    void theProposalIsRefittedToTheFailuresSmoothedAndMixedWithTheGenerator() {
        List<Sample> stage = new ArrayList<>();
        for (int i = 0; i < 95; i++) {
            stage.add(withMovingBin(i % 10, 1 + i));
        }
        for (int i = 0; i < 5; i++) {
            stage.add(withMovingBin(14, -1));
        }
        CrossEntropy.Fit fit = CrossEntropy.refit(Tilt.NOMINAL, stage, Set.of(DrawSite.MOVING_CARS), 0.05, 0.5, 0.2);
        assertEquals(5, fit.elite());
        assertEquals(-1, fit.level());
        double bin14 = 0.8 * (0.5 * 1 + 0.5 / 15) + 0.2 / 15;
        double other = 0.8 * (0.5 / 15) + 0.2 / 15;
        assertEquals(bin14, fit.tilt().probability(DrawSite.MOVING_CARS, 14), 1e-12);
        assertEquals(other, fit.tilt().probability(DrawSite.MOVING_CARS, 3), 1e-12);
        assertEquals(1.0 / 20, fit.tilt().probability(DrawSite.JUNCTION_ATTEMPTS, 0), 1e-12, "a site not fitted stays the generator's");
    }

    @Test
    void whileFailuresAreRareTheEliteIsTheQuantileOfLeastScores() {
        List<Sample> stage = new ArrayList<>();
        for (int i = 0; i < 100; i++) {
            stage.add(withMovingBin(i < 10 ? 2 : 7, i));
        }
        CrossEntropy.Fit fit = CrossEntropy.refit(Tilt.NOMINAL, stage, Set.of(DrawSite.MOVING_CARS), 0.1, 1.0, 0.0);
        assertEquals(10, fit.elite());
        assertEquals(9, fit.level());
        assertEquals(1.0, fit.tilt().probability(DrawSite.MOVING_CARS, 2), 1e-12);
    }
}
