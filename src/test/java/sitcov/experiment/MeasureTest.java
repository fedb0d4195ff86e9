package sitcov.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

class MeasureTest {
    @Test
    void everyMeasureHasItsOwnKeyAndLabel() {
        Measure[] all = Measure.values();
        assertEquals(all.length, Arrays.stream(all).map(Measure::key).distinct().count());
        assertEquals(all.length, Arrays.stream(all).map(Measure::label).distinct().count());
        for (Measure m : all) {
            assertFalse(m.label().isBlank(), m.key());
            assertEquals(m, Measure.ofKey(m.key()));
        }
    }
}
