package sitcov.world;

import sitcov.geom.Rect;

/** One painted strip on road {@code roadId}: a piece of an edge or centre line between junctions. */
public record Marking(MarkingKind kind, int roadId, Rect strip) {
}
