package sitcov.vehicles;

/**
 * How many of a fixed, never-falling list of numbers are at most a given value: what a binary search
 * answers, found instead from a table of hints over the list's range and a step or two each way.
 * The hint only says where to start; the answer is settled by the list itself, so it is exact
 * whatever the rounding in picking the hint. Immutable: shared by every thread.
 */
final class SortedLookup {
    /** Hints per key: about one key a slot, so that a step or two settles the count. */
    private static final int SLOTS_PER_KEY = 2;

    private final double[] keys;
    private final double first;
    private final double scale;
    /** Per slot, the count of keys at most the slot's low end, as near as rounding lets it be. */
    private final int[] hint;

    private SortedLookup(double[] keys) {
        this.keys = keys;
        int slots = Math.max(1, SLOTS_PER_KEY * keys.length);
        this.first = keys.length == 0 ? 0 : keys[0];
        double span = keys.length == 0 ? 0 : keys[keys.length - 1] - first;
        this.scale = span > 0 ? slots / span : 0;
        this.hint = new int[slots + 1];
        int count = 0;
        for (int slot = 0; slot <= slots; slot++) {
            double low = scale > 0 ? first + slot / scale : first;
            while (count < keys.length && keys[count] <= low) {
                count++;
            }
            hint[slot] = count;
        }
    }

    /** The lookup of {@code keys}, or null when they fall somewhere (or hold NaN): no count answers for them. */
    static SortedLookup of(double[] keys) {
        for (int k = 0; k < keys.length; k++) {
            if (Double.isNaN(keys[k]) || k > 0 && keys[k] < keys[k - 1]) {
                return null;
            }
        }
        return new SortedLookup(keys.clone());
    }

    /** How many keys are at most {@code value} (none for NaN), as a search of the list would count them. */
    int countAtMost(double value) {
        if (!(value >= first) || keys.length == 0) {
            return 0;
        }
        double at = (value - first) * scale;
        int slot = at < hint.length ? (int) at : hint.length - 1;
        int count = hint[slot];
        while (count > 0 && keys[count - 1] > value) {
            count--;
        }
        while (count < keys.length && keys[count] <= value) {
            count++;
        }
        return count;
    }
}
