package sitcov.sensors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class RayFanTest {

    @Test
    void theCamerasFansHaveFallingSlopesAndTheRunsInAnIntervalAreTheRaysALinearScanAdmits() {
        RayFan.Cache cache = new RayFan.Cache(4);
        int admitted = 0;
        for (double bearing : new double[] {0, 90, 180, 270}) {
            for (double step : new double[] {0.5, 1, 2.5, 0.1}) {
                for (boolean left : new boolean[] {true, false}) {
                    RayFan fan = left ? cache.fan(RayFan.Form.STEPPING_RIGHT, bearing, 90, 0, step)
                            : cache.fan(RayFan.Form.STEPPING_RIGHT, bearing, 0, -90, step);
                    assertTrue(fan.slopesFall(), "bearing " + bearing + " step " + step);
                    for (int ray = 0; ray < fan.size(); ray++) {
                        boolean inRun = ray >= fan.slopedFrom() && ray < fan.slopedTo();
                        assertEquals(inRun, !Double.isNaN(fan.slope(ray)), "ray " + ray);
                    }
                    for (double lo = -3; lo <= 3; lo += 0.37) {
                        for (double hi : new double[] {lo, lo + 0.01, lo + 0.5, lo + 4}) {
                            int first = fan.firstSlopeAtMost(hi);
                            int last = fan.lastSlopeAtLeast(lo);
                            for (int ray = fan.slopedFrom(); ray < fan.slopedTo(); ray++) {
                                boolean admits = !(fan.slope(ray) < lo) && !(fan.slope(ray) > hi);
                                assertEquals(admits, ray >= first && ray <= last, "ray " + ray + " in [" + lo + ", " + hi + "]");
                                admitted += admits ? 1 : 0;
                            }
                        }
                    }
                }
            }
        }
        assertTrue(admitted > 1000, "the intervals tried admit rays: " + admitted);
    }
}
