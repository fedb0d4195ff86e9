package sitcov.control;

import java.util.EnumSet;
import java.util.Optional;
import java.util.Set;

/**
 * The parts of the {@link Observation} that come from the car's sensors, each of which a controller
 * takes or not: a controller program asks at hello for the ones the protocol sends it; a controller in
 * process is handed the whole observation. Viewers draw the ones a run's controller took.
 */
public enum Sensor {
    /** Other vehicles within range, as tracks ({@link Observation#traffic}). */
    RADAR("radar"),
    /** Parked cars within range, as boxes ({@link Observation#obstacles}). */
    OBSTACLES("obstacles"),
    /** The standard camera's marking hits ({@link Observation#cameraHits}). */
    CAMERA("camera"),
    /** The standard LIDAR sweep's hits ({@link Observation#lidarHits}). */
    LIDAR("lidar");

    private final String wireName;

    Sensor(String wireName) {
        this.wireName = wireName;
    }

    /** Its name in the protocol and in recordings. */
    public String wireName() {
        return wireName;
    }

    public static Optional<Sensor> ofWireName(String name) {
        for (Sensor s : values()) {
            if (s.wireName.equals(name)) {
                return Optional.of(s);
            }
        }
        return Optional.empty();
    }

    /** Every sensor: what a controller in process is handed. */
    public static Set<Sensor> all() {
        return EnumSet.allOf(Sensor.class);
    }

    /** What a controller program that says nothing of sensors at hello takes: the objects its sensors report. */
    public static Set<Sensor> reported() {
        return EnumSet.of(RADAR, OBSTACLES);
    }

    /** The sensors as bits (1 &lt;&lt; ordinal), for a run to keep them without an object. */
    public static int bits(Set<Sensor> sensors) {
        int bits = 0;
        for (Sensor s : sensors) {
            bits |= 1 << s.ordinal();
        }
        return bits;
    }

    /** The sensors of {@link #bits}. */
    public static Set<Sensor> of(int bits) {
        Set<Sensor> sensors = EnumSet.noneOf(Sensor.class);
        for (Sensor s : values()) {
            if ((bits & 1 << s.ordinal()) != 0) {
                sensors.add(s);
            }
        }
        return sensors;
    }
}
