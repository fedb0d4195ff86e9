package sitcov.oracle;

import java.util.List;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.world.Junction;
import sitcov.world.Marking;
import sitcov.world.MarkingKind;
import sitcov.world.Road;
import sitcov.world.RoadNetwork;
import sitcov.control.SelfReport;
import sitcov.control.Vehicle;

/** Where the other lane begins: whether a footprint reaches over a road's centre line, outside junctions. */
final class CentreLine {
    private final RoadNetwork network;
    private final List<Marking> centreStrips;

    CentreLine(RoadNetwork network) {
        this.network = network;
        this.centreStrips = network.markings().stream().filter(m -> m.kind() == MarkingKind.CENTRE).toList();
    }

    /** Whether any corner of the car's footprint lies in the other lane of the road it drives along. */
    boolean isOver(Vehicle car, SelfReport said, Box body) {
        Compass lane = said.lane() == null ? Compass.nearest(car.heading()) : said.lane();
        double[] corners = body.corners();
        for (int i = 0; i < 4; i++) {
            double x = corners[2 * i];
            double y = corners[2 * i + 1];
            if (inJunction(x, y)) {
                continue;
            }
            for (Road road : network.roads()) {
                if (road.isNorthSouth() == lane.isNorthSouth() && road.contains(x, y)
                        && road.laneDirectionAt(x, y) == lane.opposite()
                        && Math.abs(road.across(x, y) - road.centre()) > 1e-9) {
                    return true;
                }
            }
        }
        return false;
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
