package sitcov.world;

import sitcov.geom.Vec2;

/** The place the autonomous car must reach, on road {@code roadId}, anywhere across its width. */
public record Target(Vec2 position, int roadId) {
}
