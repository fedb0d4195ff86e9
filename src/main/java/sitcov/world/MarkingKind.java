package sitcov.world;

/** Painted lines: an edge line near each kerb, and the centre line between the lanes. */
public enum MarkingKind {
    EDGE,
    CENTRE
}
