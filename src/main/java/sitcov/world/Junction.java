package sitcov.world;

import static sitcov.world.Dimensions.HALF_ROAD;
import static sitcov.world.Dimensions.JUNCTION_SIZE;

import java.util.ArrayList;
import java.util.List;
import sitcov.geom.Compass;
import sitcov.geom.Rect;
import sitcov.geom.Vec2;

/**
 * A 6 m square where roads meet: a T-junction (three arms) where a branch leaves its parent road,
 * or a dead end (one arm) at a road end. An arm's length is how far road extends from the centre
 * in that direction, capped at the 23 m approach length; 0 means no arm.
 */
public record Junction(int id, Vec2 centre, double armNorth, double armEast, double armSouth, double armWest) {

    public double arm(Compass direction) {
        return switch (direction) {
            case NORTH -> armNorth;
            case EAST -> armEast;
            case SOUTH -> armSouth;
            case WEST -> armWest;
        };
    }

    public boolean hasArm(Compass direction) {
        return arm(direction) > 0;
    }

    /** The directions with an arm, in compass order N, E, S, W. */
    public List<Compass> arms() {
        List<Compass> arms = new ArrayList<>(4);
        for (Compass c : Compass.values()) {
            if (hasArm(c)) {
                arms.add(c);
            }
        }
        return arms;
    }

    public boolean isDeadEnd() {
        return arms().size() == 1;
    }

    public JunctionKind kind() {
        return isDeadEnd() ? JunctionKind.DEAD_END : JunctionKind.T_JUNCTION;
    }

    public Rect square() {
        return Rect.square(centre.x(), centre.y(), JUNCTION_SIZE);
    }

    public boolean contains(double x, double y) {
        // the tolerance absorbs rounding in coordinates that are meant to lie exactly on an edge
        return Math.abs(x - centre.x()) <= HALF_ROAD + 1e-9 && Math.abs(y - centre.y()) <= HALF_ROAD + 1e-9;
    }

    /** The square plus, on every arm, the lane carrying traffic towards the junction. */
    public List<Rect> approachZone() {
        return zone(true);
    }

    /** The square plus, on every arm, the lane carrying traffic away from the junction. */
    public List<Rect> exitZone() {
        return zone(false);
    }

    /** The centre of the lane leaving through arm {@code direction}, {@code beyond} metres past the square. */
    public Vec2 exitPoint(Compass direction, double beyond) {
        double along = HALF_ROAD + beyond;
        double side = Dimensions.LANE_WIDTH / 2;
        // the lane leaving in a direction lies on the driver's left (left-hand traffic)
        Compass left = direction.left();
        return new Vec2(centre.x() + direction.dx() * along + left.dx() * side,
                centre.y() + direction.dy() * along + left.dy() * side);
    }

    private List<Rect> zone(boolean towards) {
        List<Rect> zone = new ArrayList<>(5);
        zone.add(square());
        for (Compass arm : arms()) {
            // Traffic towards the junction on this arm drives arm.opposite(), on its own left,
            // which is the arm's right-hand side seen from the centre.
            Compass side = towards ? arm.right() : arm.left();
            double near = HALF_ROAD;
            double far = arm(arm);
            if (far <= near) {
                continue;
            }
            double x1 = centre.x() + arm.dx() * near;
            double y1 = centre.y() + arm.dy() * near;
            double x2 = centre.x() + arm.dx() * far + side.dx() * HALF_ROAD;
            double y2 = centre.y() + arm.dy() * far + side.dy() * HALF_ROAD;
            zone.add(Rect.spanning(x1, y1, x2, y2));
        }
        return zone;
    }
}
