package sitcov.world;

/** The two kinds of junction a generated map has. */
public enum JunctionKind {
    T_JUNCTION,
    DEAD_END
}
