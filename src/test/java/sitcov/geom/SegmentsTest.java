package sitcov.geom;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class SegmentsTest {

    @Test
    void clippingKeepsThePartInsideTheRectangle() {
        assertArrayEquals(new double[] {0.25, 0.75}, Segments.clip(0, 5, 20, 5, new Rect(5, 0, 15, 10)), 1e-12);
        assertNull(Segments.clip(0, 20, 20, 20, new Rect(5, 0, 15, 10)));
    }

    @Test
    void aSegmentIsCoveredWhenTheRectanglesLeaveNoGap() {
        List<Rect> joined = List.of(new Rect(0, 0, 10, 2), new Rect(10, 0, 20, 2));
        List<Rect> gapped = List.of(new Rect(0, 0, 9, 2), new Rect(10, 0, 20, 2));

        assertTrue(Segments.isCovered(1, 1, 19, 1, joined));
        assertFalse(Segments.isCovered(1, 1, 19, 1, gapped));
        assertFalse(Segments.isCovered(1, 1, 19, 3, joined));
    }
}
