package sitcov.engine;

import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Map;
import java.util.random.RandomGenerator;

/**
 * Splits one root seed into named, independent streams. A stream's seed depends only on the root
 * and its label, so adding a new consumer (a new label) never shifts the numbers of another stream,
 * and the same (root, label) gives the same sequence on every machine and JDK.
 *
 * <p>The generator is SplitMix64 ({@link SplitMix}, the numbers of the JDK's {@code SplittableRandom}),
 * whose algorithm is fixed by its specification. Instances are not thread-safe: each run owns its own streams.
 */
public final class RandomStreams {
    private static final long FNV_OFFSET = 0xcbf29ce484222325L;
    private static final long FNV_PRIME = 0x100000001b3L;
    private static final long GOLDEN_GAMMA = 0x9e3779b97f4a7c15L;

    private long root;
    private Map<String, RandomGenerator> streams = new HashMap<>();

    public RandomStreams(long root) {
        this.root = root;
    }

    public long root() {
        return root;
    }

    /**
     * The stream named {@code label}. Asking twice for one label returns the same object, so two
     * consumers of a label share (and advance) one sequence rather than silently repeating it.
     */
    public RandomGenerator stream(String label) {
        return streams.computeIfAbsent(checked(label), l -> new SplitMix(seedFor(l)));
    }

    /** The seed the stream {@code label} starts from; use it to seed a child run or map. */
    public long seedFor(String label) {
        return mix(root, checked(label));
    }

    /** A fresh family of streams rooted at {@link #seedFor(String) seedFor(label)}. */
    public RandomStreams derive(String label) {
        return new RandomStreams(seedFor(label));
    }

    /** Mixes a root seed with a label: FNV-1a of the label's UTF-8 bytes, then SplitMix64 finalisers. */
    public static long mix(long root, String label) {
        long hash = FNV_OFFSET;
        for (byte b : label.getBytes(StandardCharsets.UTF_8)) {
            hash = (hash ^ (b & 0xff)) * FNV_PRIME;
        }
        return finalise(finalise(root ^ finalise(hash)) + GOLDEN_GAMMA);
    }

    private static long finalise(long z) {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    private static String checked(String label) {
        if (label == null || label.isBlank()) {
            throw new IllegalArgumentException("a random stream needs a non-blank label");
        }
        return label;
    }
}
