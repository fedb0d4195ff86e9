package sitcov.world;

import java.util.ArrayList;
import java.util.List;
import sitcov.geom.Box;
import sitcov.geom.Vec2;

/** A parked car: 5 m × 2 m, centred on {@code centre}, its long side along its road, against a kerb. */
public record ParkedCar(int id, int roadId, Vec2 centre, Axis axis) {
    public Box footprint() {
        return Box.centred(centre.x(), centre.y(), axis.bearing(), Dimensions.CAR_LENGTH, Dimensions.CAR_WIDTH);
    }

    /** The cars in order, each with its index as its id, as situation files number them. */
    static List<ParkedCar> numbered(List<ParkedCar> cars) {
        List<ParkedCar> out = new ArrayList<>(cars.size());
        for (ParkedCar c : cars) {
            out.add(new ParkedCar(out.size(), c.roadId(), c.centre(), c.axis()));
        }
        return out;
    }
}
