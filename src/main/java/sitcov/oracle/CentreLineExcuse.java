package sitcov.oracle;

import java.util.List;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Rect;
import sitcov.world.Axis;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.ParkedCar;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;

/**
 * When being over the centre line is justified, judged from what anyone sees of the car — its
 * footprint (and so its heading), the roads, the junctions and the parked cars — never from what
 * the car says it is doing (faults/README.md, "The car under test, the traffic and the oracle"):
 *
 * <ul>
 *   <li><b>at a junction</b>: any part of the footprint is in a junction's square or within
 *       {@value #JUNCTION_MARGIN} m of it — the 0.5 m of body behind the rear axle, about which the
 *       car turns, swings out — or, leaving the junction (its centre behind the middle of the
 *       footprint), within {@value #LEAVING_MARGIN} m of it. The car's own crossing ends once its front
 *       is 3.5 m past the square (the exit waypoint 1.5 m beyond it, then half the 4 m tail of the
 *       crossing path), its rear then 1.5 m past; add the 0.5 m swing. A tight left turn can overshoot
 *       and weave back: the fault-free car was over the line up to 1.2 m past a square it was leaving
 *       on maps 10001..12000 (1.0 m on 20001..22000, never past it on 1..2000 and 30001..32000). A car
 *       swerving over the line as it drives up to a junction is not excused beyond the 0.5 m.</li>
 *   <li><b>passing an obstacle</b>: a parked car stands in the lane the car drives — on the road under
 *       the middle of its footprint, in the half whose legal direction is the direction along that
 *       road nearest the car's heading — beside the footprint, or with its near end at most
 *       {@value #BEFORE_OBSTACLE} m ahead of the footprint's middle, or its far end at most
 *       {@value #AFTER_OBSTACLE} m behind it; or the footprint's middle is in a gap of at most
 *       {@value #ROW_GAP} m between two cars parked in that lane. The distances follow the car's
 *       overtaking ({@code Overtaker}): it pulls out when the parked car is {@code HEADWAY} (7 m) plus
 *       a tick's travel (at most 2.5 m) ahead of its front, 1 m ahead of the footprint's middle — at
 *       most 10.5 m; it stays out until its front is {@code BUFFER} + 1 (3 m) past the row, comes back
 *       in over {@code HEADWAY} more (its middle then 9 m past) and straightens up. Out there it looks
 *       again, and another car parked in its lane within the LIDAR's 25 m keeps it out: a gap of up to
 *       3 + 25 = 28 m in a row is driven in the other lane. On maps 1..2000, 10001..12000 and
 *       20001..22000 the fault-free car, over the line while passing, was never outside these (pulling
 *       out, the near end at most 8.2 m ahead; pulling in, the far end at most 12.6 m behind), nor on
 *       maps 30001..32000, which were not used to choose them. So a pull-out before an obstacle, a
 *       pull-in after it and a gap in a row are excused, and driving on the wrong side farther on is
 *       not.</li>
 * </ul>
 *
 * <p>Asked only when the footprint is over the line, so it costs nothing on most ticks, and it
 * allocates nothing.
 */
final class CentreLineExcuse {
    /** How near a junction's square any part of the footprint may be, metres. */
    static final double JUNCTION_MARGIN = 0.5;
    /** How near the square of a junction it is leaving any part of the footprint may be, metres. */
    static final double LEAVING_MARGIN = 2.0;
    /** How far ahead of the footprint's middle a parked car's near end may be, metres along the road. */
    static final double BEFORE_OBSTACLE = 12.0;
    /** How far behind the footprint's middle a parked car's far end may be, metres along the road. */
    static final double AFTER_OBSTACLE = 13.0;
    /** The longest gap in a row of parked cars that the car drives across in the other lane, metres. */
    static final double ROW_GAP = 28.0;

    private static final double HALF_PARKED = Dimensions.CAR_LENGTH / 2;

    /** Each junction's square grown by the margin on every side. */
    private Rect[] junctionZones;
    /** Each junction's square grown by the leaving margin on every side, and its centre. */
    private Rect[] leavingZones;
    private double[] junctionX;
    private double[] junctionY;
    private Road[] roads;
    private double[] parkedX;
    private double[] parkedY;
    private Axis[] parkedAxis;

    CentreLineExcuse(RoadNetwork network, List<ParkedCar> parked) {
        List<Junction> junctions = network.junctions();
        this.junctionZones = new Rect[junctions.size()];
        this.leavingZones = new Rect[junctions.size()];
        this.junctionX = new double[junctions.size()];
        this.junctionY = new double[junctions.size()];
        for (int i = 0; i < junctionZones.length; i++) {
            Junction j = junctions.get(i);
            junctionX[i] = j.centre().x();
            junctionY[i] = j.centre().y();
            junctionZones[i] = Rect.square(junctionX[i], junctionY[i], Dimensions.JUNCTION_SIZE + 2 * JUNCTION_MARGIN);
            leavingZones[i] = Rect.square(junctionX[i], junctionY[i], Dimensions.JUNCTION_SIZE + 2 * LEAVING_MARGIN);
        }
        this.roads = network.roads().toArray(new Road[0]);
        this.parkedX = new double[parked.size()];
        this.parkedY = new double[parked.size()];
        this.parkedAxis = new Axis[parked.size()];
        for (int i = 0; i < parkedX.length; i++) {
            parkedX[i] = parked.get(i).centre().x();
            parkedY[i] = parked.get(i).centre().y();
            parkedAxis[i] = parked.get(i).axis();
        }
    }

    /** Whether a footprint over the centre line is there for a reason anyone can see. */
    boolean applies(Box body) {
        return isAtJunction(body) || isPassingObstacle(body);
    }

    /** Whether any part of the footprint is near a junction's square: within the margin, or the leaving margin when leaving it. */
    boolean isAtJunction(Box body) {
        double cx = body.centreX();
        double cy = body.centreY();
        double dx = Bearing.dx(body.bearing());
        double dy = Bearing.dy(body.bearing());
        for (int i = 0; i < junctionZones.length; i++) {
            if (body.overlaps(junctionZones[i])) {
                return true;
            }
            boolean leaving = (junctionX[i] - cx) * dx + (junctionY[i] - cy) * dy < 0;
            if (leaving && body.overlaps(leavingZones[i])) {
                return true;
            }
        }
        return false;
    }

    /** Whether a parked car in the lane the footprint drives is near enough along the road to be passed. */
    boolean isPassingObstacle(Box body) {
        double cx = body.centreX();
        double cy = body.centreY();
        Road road = roadAt(cx, cy);
        if (road == null) {
            return false;
        }
        Compass lane = CentreLine.laneOn(road, Bearing.dx(body.bearing()), Bearing.dy(body.bearing()));
        // along-road coordinates grow to the south and east: forward is +1 there
        int forward = lane.dx() + lane.dy();
        double middle = road.along(cx, cy);
        // the nearest parked car in the lane wholly ahead (its near end) and wholly behind (its far end)
        double nearestAhead = Double.POSITIVE_INFINITY;
        double nearestBehind = Double.POSITIVE_INFINITY;
        for (int i = 0; i < parkedX.length; i++) {
            double px = parkedX[i];
            double py = parkedY[i];
            if (parkedAxis[i] != road.axis() || !road.contains(px, py) || road.laneDirectionAt(px, py) != lane) {
                continue;
            }
            double ahead = (road.along(px, py) - middle) * forward;
            double nearEnd = ahead - HALF_PARKED;
            double farEndBehind = -(ahead + HALF_PARKED);
            if (nearEnd <= 0 && farEndBehind <= 0) {
                return true; // beside it
            }
            if (nearEnd > 0) {
                nearestAhead = Math.min(nearestAhead, nearEnd);
            } else {
                nearestBehind = Math.min(nearestBehind, farEndBehind);
            }
        }
        return nearestAhead <= BEFORE_OBSTACLE || nearestBehind <= AFTER_OBSTACLE
                || nearestAhead + nearestBehind <= ROW_GAP;
    }

    private Road roadAt(double x, double y) {
        for (Road road : roads) {
            if (road.contains(x, y)) {
                return road;
            }
        }
        return null;
    }
}
