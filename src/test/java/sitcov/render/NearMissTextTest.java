package sitcov.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import sitcov.oracle.AccidentType;
import sitcov.oracle.NearMiss;

class NearMissTextTest {
    @Test
    void gapsAndMarginsAreInMetresAndTheTimesInTicks() {
        assertEquals("0.47 m", NearMissText.value(NearMiss.PARKED_GAP, 0.4711, 2));
        assertEquals("-0.1028 m", NearMissText.value(NearMiss.ROAD_EDGE, -0.1028, 4));
        assertEquals("4.9 ticks", NearMissText.value(NearMiss.TIME_TO_COLLISION, 4.8643, 1));
        assertEquals("7 ticks", NearMissText.value(NearMiss.POST_ENCROACHMENT, 7, 4), "whole ticks");
        assertEquals("4250 ticks", NearMissText.rho(AccidentType.TIMEOUT, 4250, 4), "whole ticks");
        assertEquals("0.0350 m", NearMissText.rho(AccidentType.CROSSCENTRELINE, 0.035, 4));
    }

    @Test
    void anUnmetMeasureIsNeverAnUnknownOneUnknownAndATouchZero() {
        assertEquals("never", NearMissText.value(NearMiss.PARKED_GAP, Double.POSITIVE_INFINITY, 2));
        assertEquals("unknown", NearMissText.rho(AccidentType.TIMEOUT, Double.NaN, 2));
        assertEquals("0.00 m", NearMissText.value(NearMiss.MOVING_GAP, -1e-10, 2));
    }

    @Test
    void eachMeasureInMetresBelowZeroIsTheAccidentOfItsRobustness() {
        for (NearMiss m : NearMiss.values()) {
            AccidentType t = NearMissText.accident(m);
            if (t != null) {
                assertEquals("m", NearMissText.unit(m));
                assertEquals("m", NearMissText.unit(t));
            } else {
                assertEquals("ticks", NearMissText.unit(m));
            }
        }
    }
}
