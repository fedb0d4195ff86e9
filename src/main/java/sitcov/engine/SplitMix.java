package sitcov.engine;

import java.util.random.RandomGenerator;

/**
 * SplitMix64 with the golden gamma: the numbers {@link java.util.SplittableRandom#SplittableRandom(long)}
 * gives for the same seed, from every method of {@link RandomGenerator}, because those all derive
 * from {@link #nextInt()} and {@link #nextLong()} as they do there. Unlike the JDK's generator its
 * state can be copied, so a checkpointed run continues with exactly the numbers it would have drawn.
 */
public final class SplitMix implements RandomGenerator {
    private static final long GOLDEN_GAMMA = 0x9e3779b97f4a7c15L;

    private long seed;

    public SplitMix(long seed) {
        this.seed = seed;
    }

    /** A generator in this one's state: both now draw the same numbers, independently. */
    public SplitMix copy() {
        return new SplitMix(seed);
    }

    @Override
    public long nextLong() {
        long z = seed += GOLDEN_GAMMA;
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    @Override
    public int nextInt() {
        long z = seed += GOLDEN_GAMMA;
        z = (z ^ (z >>> 33)) * 0x62a9d9ed799705f5L;
        return (int) (((z ^ (z >>> 28)) * 0xcb24d0a5c88c35b3L) >>> 32);
    }
}
