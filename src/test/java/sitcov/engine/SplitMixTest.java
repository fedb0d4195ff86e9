package sitcov.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import java.util.random.RandomGenerator;
import org.junit.jupiter.api.Test;

class SplitMixTest {
    private static final long[] SEEDS = {0, 1, -1, 42, Long.MIN_VALUE, Long.MAX_VALUE, 0x9e3779b97f4a7c15L, 123456789L};

    @Test
    void drawsWhatTheJdksSplittableRandomDrawsFromEveryMethodRunsUse() {
        for (long seed : SEEDS) {
            RandomGenerator jdk = new SplittableRandom(seed);
            RandomGenerator ours = new SplitMix(seed);
            for (int i = 0; i < 2000; i++) {
                String at = "seed " + seed + " draw " + i;
                assertEquals(jdk.nextLong(), ours.nextLong(), at);
                assertEquals(jdk.nextInt(), ours.nextInt(), at);
                assertEquals(jdk.nextDouble(), ours.nextDouble(), at);
                assertEquals(jdk.nextBoolean(), ours.nextBoolean(), at);
                assertEquals(jdk.nextInt(1 + i % 37), ours.nextInt(1 + i % 37), at);
                assertEquals(jdk.nextInt(64), ours.nextInt(64), at);
                assertEquals(jdk.nextInt(-5, 1000 + i), ours.nextInt(-5, 1000 + i), at);
                assertEquals(jdk.nextDouble(2.5, 7 + i), ours.nextDouble(2.5, 7 + i), at);
                assertEquals(jdk.nextLong(3 + i), ours.nextLong(3 + i), at);
                assertEquals(jdk.nextGaussian(), ours.nextGaussian(), at);
                assertEquals(jdk.nextFloat(), ours.nextFloat(), at);
            }
        }
    }

    @Test
    void aCopyDrawsTheSameNumbersAsTheOriginalWithoutAdvancingIt() {
        SplitMix original = new SplitMix(7);
        original.nextLong();
        SplitMix copy = original.copy();
        long[] fromCopy = {copy.nextLong(), copy.nextLong(), copy.nextLong()};
        long[] fromOriginal = {original.nextLong(), original.nextLong(), original.nextLong()};
        assertEquals(java.util.Arrays.toString(fromOriginal), java.util.Arrays.toString(fromCopy));
    }
}
