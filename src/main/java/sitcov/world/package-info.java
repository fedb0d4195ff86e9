/**
 * The static world: roads, junctions, parked cars, the Target and start poses ({@link sitcov.world.Layout},
 * {@link sitcov.world.WorldMap}); the seeded {@link sitcov.world.MapGenerator}; the spatial queries of
 * {@link sitcov.world.RoadNetwork}; and situation files. Traffic keeps to the left.
 */
package sitcov.world;
