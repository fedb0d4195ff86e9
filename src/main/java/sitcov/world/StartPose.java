package sitcov.world;

import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;

/** Where a vehicle starts: its front centre on a lane centre, facing the lane's legal direction. */
public record StartPose(Vec2 position, Compass heading) {
    /** The footprint of a vehicle of this size standing here (anchored at its front centre). */
    public Box footprint(double length, double width) {
        return Box.behind(position.x(), position.y(), heading.bearing(), length, width);
    }
}
