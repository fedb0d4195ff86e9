package sitcov.control;

import java.util.List;
import sitcov.geom.Box;
import sitcov.world.RoadNetwork;
import sitcov.world.Target;

/**
 * What the car under test observes in one tick (experiments/controllers/README.md, "Testing your own controller"):
 * its own pose
 * and speed (odometry), the road map and the Target it navigates by, the objects its sensors report
 * within {@link #SENSOR_RANGE} (other vehicles as radar tracks, parked cars as LIDAR obstacles), the
 * standard camera's and LIDAR's raw hits, the junctions' right-of-way, and any ground-truth channel
 * it asked for. Valid only during the {@link Controller#step} it is handed to.
 */
public interface Observation {
    /** Radar and LIDAR report objects whose anchor lies within this many metres of the car's front. */
    double SENSOR_RANGE = 80;

    long tick();

    /** The x of the car's front centre. */
    double x();

    double y();

    /** Bearing in degrees (0 south, 90 east, 180 north, 270 west), in [0, 360). */
    double heading();

    /** Metres per tick. */
    double speed();

    /** The road map: roads, junctions and painted markings. */
    RoadNetwork roads();

    Target target();

    /** Other vehicles on the map within range, in vehicle order: radar tracks. */
    List<Vehicle> traffic();

    /** Parked cars within range, in map order: the LIDAR's obstacles. */
    List<Box> obstacles();

    RightOfWay rightOfWay();

    /** The standard road-marking camera's hits, looking along the compass direction nearest the heading. */
    int cameraHits();

    double cameraHitX(int hit);

    double cameraHitY(int hit);

    /** The standard LIDAR sweep's hits, 180° around the heading. */
    int lidarHits();

    double lidarHitX(int hit);

    double lidarHitY(int hit);

    /** Ground truth on request: the channel's value now (NaN where it has none, e.g. no junction ahead). */
    double channel(Channel channel);
}
