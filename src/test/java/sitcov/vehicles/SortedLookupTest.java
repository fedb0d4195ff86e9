package sitcov.vehicles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class SortedLookupTest {

    @Test
    void countsTheKeysAtMostAValueAsALinearCountDoes() {
        SplittableRandom random = new SplittableRandom(7);
        for (int trial = 0; trial < 200; trial++) {
            double[] keys = new double[random.nextInt(0, 40)];
            for (int k = 0; k < keys.length; k++) {
                // repeated keys and a crowded end, as tables of stopping distances have
                keys[k] = random.nextInt(4) == 0 && k > 0 ? keys[k - 1] : Math.pow(random.nextDouble(0, 3), 3);
            }
            Arrays.sort(keys);
            SortedLookup lookup = SortedLookup.of(keys);
            assertNotNull(lookup);
            for (double key : keys) {
                for (double value : new double[] {Math.nextDown(key), key, Math.nextUp(key)}) {
                    assertEquals(linearCount(keys, value), lookup.countAtMost(value), "value " + value);
                }
            }
            for (double value : new double[] {-1, 0, 1e-300, 13.5, 27, 100, Double.POSITIVE_INFINITY,
                    Double.NEGATIVE_INFINITY, Double.NaN}) {
                assertEquals(linearCount(keys, value), lookup.countAtMost(value), "value " + value);
            }
        }
    }

    @Test
    void aListThatFallsOrHoldsNaNHasNoLookup() {
        assertNull(SortedLookup.of(new double[] {1, 2, 1.5}));
        assertNull(SortedLookup.of(new double[] {1, Double.NaN}));
        assertNotNull(SortedLookup.of(new double[] {1, 1, 1}));
    }

    private static int linearCount(double[] keys, double value) {
        int count = 0;
        for (double key : keys) {
            if (key <= value) {
                count++;
            }
        }
        return count;
    }
}
