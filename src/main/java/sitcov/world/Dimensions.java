package sitcov.world;

/**
 * The world's fixed measures, in metres and seconds (src/main/java/sitcov/cli/README.md, "Maps and situation files",
 * and faults/README.md, "The car under test, the traffic and the oracle").
 */
public final class Dimensions {
    /** A tick's length: the car's top speed of 2.5 m a tick is 45 km/h. */
    public static final double TICK_SECONDS = 0.2;
    public static final double WORLD_WIDTH = 200;
    public static final double WORLD_HEIGHT = 100;
    public static final double ROAD_WIDTH = 6;
    public static final double LANE_WIDTH = 3;
    public static final double HALF_ROAD = ROAD_WIDTH / 2;
    /** Edge lines are this far in from the kerb, and this wide. */
    public static final double EDGE_LINE_OFFSET = 0.225;
    public static final double EDGE_LINE_WIDTH = 0.1;
    public static final double CENTRE_LINE_WIDTH = 0.1;
    public static final double JUNCTION_SIZE = 6;
    /** Approach and exit zones reach this far along each arm from a junction's centre (20 + ceil(2.5)). */
    public static final double APPROACH_LENGTH = 23;
    public static final double MIN_ROAD_LENGTH = 23;
    /** A junction's centre is at least this far from either end of its road (1.5 road widths). */
    public static final double JUNCTION_END_MARGIN = 9;
    public static final double CAR_LENGTH = 5;
    public static final double CAR_WIDTH = 2;
    public static final double AUTONOMOUS_CAR_LENGTH = 2;
    public static final double AUTONOMOUS_CAR_WIDTH = 2;
    /** Coordinates of generated maps are rounded to this step, so situation files stay short. */
    public static final double COORDINATE_STEP = 0.001;

    private Dimensions() {
    }

    /** {@code v} rounded to the coordinate step (a millimetre). */
    public static double rounded(double v) {
        double r = Math.round(v * 1000) / 1000.0;
        return r == 0 ? 0.0 : r; // never -0.0, so files and equality stay canonical
    }
}
