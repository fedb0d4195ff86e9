package sitcov.oracle;

import java.util.List;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.world.Junction;
import sitcov.world.Marking;
import sitcov.world.MarkingKind;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;

/**
 * Where the other lane begins: whether a footprint reaches over a road's centre line, outside
 * junctions. The lane is judged from the footprint alone, never from what the car believes (faults/README.md, "The
 * car under test, the traffic and the oracle"): on each road, the direction along it nearest the
 * car's heading — so a car turned sharply across its road is still judged against that road.
 */
final class CentreLine {
    private RoadNetwork network;
    private List<Marking> centreStrips;

    CentreLine(RoadNetwork network) {
        this.network = network;
        this.centreStrips = network.markings().stream().filter(m -> m.kind() == MarkingKind.CENTRE).toList();
    }

    /** {@link #isOver(Box, double, double)} for a footprint whose heading's unit vector is not at hand. */
    boolean isOver(Box body) {
        return isOver(body, Bearing.dx(body.bearing()), Bearing.dy(body.bearing()));
    }

    /**
     * Whether any corner of the footprint, outside junction squares, lies in the half of a road that
     * carries traffic against the car: the car faces along (headingDx, headingDy), its heading's unit
     * vector.
     */
    boolean isOver(Box body, double headingDx, double headingDy) {
        double[] corners = body.corners();
        for (int i = 0; i < 4; i++) {
            double x = corners[2 * i];
            double y = corners[2 * i + 1];
            if (inJunction(x, y)) {
                continue;
            }
            for (int index : network.roadsNear(x, y)) {
                Road road = network.roads().get(index);
                if (road.contains(x, y) && road.laneDirectionAt(x, y) == laneOn(road, headingDx, headingDy).opposite()
                        && Math.abs(road.across(x, y) - road.centre()) > 1e-9) {
                    return true;
                }
            }
        }
        return false;
    }

    /** The direction along {@code road} nearest a heading: the lane a car facing that way drives on it. */
    static Compass laneOn(Road road, double headingDx, double headingDy) {
        if (road.isNorthSouth()) {
            // north is −y
            return headingDy < 0 ? Compass.NORTH : Compass.SOUTH;
        }
        return headingDx >= 0 ? Compass.EAST : Compass.WEST;
    }

    /** Whether the footprint touches a painted centre line. */
    boolean touches(Box body) {
        for (Marking m : centreStrips) {
            if (body.overlaps(m.strip())) {
                return true;
            }
        }
        return false;
    }

    private boolean inJunction(double x, double y) {
        for (Junction j : network.junctions()) {
            if (j.contains(x, y)) {
                return true;
            }
        }
        return false;
    }
}
