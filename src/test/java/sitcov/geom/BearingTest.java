package sitcov.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class BearingTest {
    private static final double EPS = 1e-9;

    @Test
    void bearingZeroMovesSouthAndNinetyMovesEast() {
        assertEquals(0, Bearing.dx(0), EPS);
        assertEquals(1, Bearing.dy(0), EPS);
        assertEquals(1, Bearing.dx(90), EPS);
        assertEquals(-1, Bearing.dy(180), EPS);
        assertEquals(-1, Bearing.dx(270), EPS);
    }

    @Test
    void theBearingBetweenTwoPointsFollowsTheCompass() {
        assertEquals(0, Bearing.between(0, 0, 0, 5), EPS);
        assertEquals(90, Bearing.between(0, 0, 5, 0), EPS);
        assertEquals(180, Bearing.between(0, 0, 0, -5), EPS);
        assertEquals(270, Bearing.between(0, 0, -5, 0), EPS);
        assertEquals(45, Bearing.between(0, 0, 1, 1), EPS);
    }

    @Test
    void normalisingBringsAnyAngleIntoOneTurn() {
        assertEquals(350, Bearing.normalise(-10), EPS);
        assertEquals(10, Bearing.normalise(730), EPS);
        assertEquals(0, Bearing.normalise(360), EPS);
    }

    @Test
    void theTurnBetweenBearingsIsTheShortWayRoundAndPositiveToTheLeft() {
        assertEquals(20, Bearing.turn(350, 10), EPS);
        assertEquals(-20, Bearing.turn(10, 350), EPS);
        assertEquals(180, Bearing.turn(0, 180), EPS);
    }

    @Test
    void cosAndSinOfDegreesAreMathsOwnToTheBitWhetherLookedUpOrNot() {
        double[] degrees = {0.0, -0.0, 90, -90, 180, -180, 270, -270, 360, -360, 450, -450, 45, 89.99999999, 1e-300,
            -1e-300, 15, 359.5, -0.5, 123.456, Double.NaN};
        for (double d : degrees) {
            assertEquals(Double.doubleToRawLongBits(Math.cos(Math.toRadians(d))), Double.doubleToRawLongBits(Bearing.cos(d)),
                    "cos " + d);
            assertEquals(Double.doubleToRawLongBits(Math.sin(Math.toRadians(d))), Double.doubleToRawLongBits(Bearing.sin(d)),
                    "sin " + d);
        }
    }
}
