package sitcov.control;

/**
 * The junctions' right-of-way, as a signal would show it to the car: whether it holds a junction,
 * and whether it would be given one it asked for now. A car asks for a junction, and lets it go,
 * through its {@link Command}; the world answers in the next observation.
 */
public interface RightOfWay {
    /** Whether the car holds junction {@code junction} (by id, in map order). */
    boolean holds(int junction);

    /**
     * Whether asking for {@code junction} now would give it to the car: it holds it already, or it is
     * free (or its holder has kept it past the world's patience) and no other vehicle is in its square.
     */
    boolean wouldGrant(int junction);
}
