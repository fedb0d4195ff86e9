package sitcov.sensors;

/**
 * Where the car believes its lane is, from the markings its camera saw: the lateral offset of
 * the lane centre from the car's front centre, positive to the right, in the frame of the lane
 * direction. Without any marking in sight the car assumes it is centred.
 */
public record LaneEstimate(boolean edgeSeen, double edgeOffset, boolean centreSeen, double centreOffset) {
    /** Lane centre to kerb-side edge line: 1.5 m − (0.225 + 0.05) m. */
    public static final double EDGE_TO_LANE_CENTRE = 1.225;
    /** Lane centre to the centre line. */
    public static final double CENTRE_TO_LANE_CENTRE = 1.5;

    public static final LaneEstimate NOTHING_SEEN = new LaneEstimate(false, 0, false, 0);

    public boolean anySeen() {
        return edgeSeen || centreSeen;
    }

    /** The lane centre's offset to the right of the car (0 when no marking was seen). */
    public double laneCentre() {
        if (edgeSeen && centreSeen) {
            return ((edgeOffset + EDGE_TO_LANE_CENTRE) + (centreOffset - CENTRE_TO_LANE_CENTRE)) / 2;
        }
        if (edgeSeen) {
            return edgeOffset + EDGE_TO_LANE_CENTRE;
        }
        if (centreSeen) {
            return centreOffset - CENTRE_TO_LANE_CENTRE;
        }
        return 0;
    }
}
