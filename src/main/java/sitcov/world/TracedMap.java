package sitcov.world;

/** A map drawn under a proposal ({@link MapGenerator#generate(long, Tilt)}), with the trace of its key draws. */
public record TracedMap(WorldMap map, DrawTrace trace) {
}
