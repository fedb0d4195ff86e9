package sitcov.seam;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.function.Function;
import java.util.random.RandomGenerator;
import java.util.stream.Collectors;
import sitcov.control.Channel;
import sitcov.engine.RandomStreams;
import sitcov.sensors.Lidar;

/**
 * The catalogue of seam faults (faults/README.md, "Seam faults"): sensor and actuator faults that act
 * on any controller at the seam, each one thing with one name, one line of doc and its parameters
 * fixed here. A fault's randomness comes from the run's stream {@code seam.NAME}, which no other part
 * of a run draws from. A variant names one as {@code seam:NAME}; {@code seam:ALL} is the catalogue.
 */
public enum SeamFault {
    RADAR_DROPOUT("radar-dropout", "the radar reports no track at all on 10% of ticks (drawn tick by tick)",
            s -> new RadarDropout(s, 0.10)),
    RADAR_HALF_RANGE("radar-half-range", "the radar reports only tracks within 40 m of the car's front (half its range)",
            s -> new TrafficWithin(40)),
    PARKED_CARS_BEYOND_15M("parked-cars-beyond-15m", "parked cars whose centre lies more than 15 m away are missing from"
            + " the LIDAR's obstacles", s -> new ObstaclesWithin(15)),
    CAMERA_BLIND_RIGHT("camera-blind-right", "the road-marking camera loses every hit to the right of the heading (the"
            + " centre line's side)", s -> new CameraOneSide()),
    LIDAR_HALF_RANGE("lidar-half-range", "the LIDAR sweep's raw hits beyond 12.5 m of the car's front (half its range)"
            + " are lost", s -> new LidarWithin(Lidar.RANGE / 2)),
    FROZEN_FRAME("frozen-frame", "with a 2% chance a tick, the observation freezes: the same frame is handed over for"
            + " 5 ticks", s -> new FrozenFrame(s, 0.02, 5)),
    LATE_FRAME("late-frame", "every observation arrives 2 ticks (0.4 s) late", s -> new LateFrame(2)),
    POSE_NOISE("pose-noise", "the car's own x and y are reported with normal noise of 0.2 m, its heading of 1 degree,"
            + " drawn each tick", s -> new PoseNoise(s, 0.2, 1)),
    LANE_OFFSET_BIAS("lane-offset-bias", "the ground-truth channel lane_offset reads 0.5 m too far to the right",
            s -> new ChannelBias(Channel.LANE_OFFSET, 0.5)),
    RIGHT_OF_WAY_STUCK("right-of-way-stuck", "the right-of-way signal is stuck at 'would grant' for every junction",
            s -> new AlwaysGranted()),
    STEERING_BIAS("steering-bias", "the steering adds 2 degrees to the left to every turn asked for",
            s -> new SteeringBias(2)),
    STEERING_STUCK("steering-stuck", "with a 2% chance a tick, the steering sticks for 5 ticks at the turn it carried"
            + " out last", s -> new SteeringStuck(s, 0.02, 5)),
    HALF_BRAKING("half-braking", "the brakes bite at half strength: every decrease of speed is halved",
            s -> new HalfBraking(0.5)),
    LATE_COMMAND("late-command", "every command's speed and steering are carried out 2 ticks (0.4 s) late",
            s -> new LateCommand(2));

    /** How a variant names the whole catalogue. */
    public static final String ALL = "seam:ALL";
    private static final String PREFIX = "seam:";

    private final String label;
    private final String description;
    private final Function<RandomGenerator, Distortion> make;

    SeamFault(String label, String description, Function<RandomGenerator, Distortion> make) {
        this.label = label;
        this.description = description;
        this.make = make;
    }

    /** Its name: lower case, words joined by '-'. */
    public String label() {
        return label;
    }

    /** One line: what it does. */
    public String description() {
        return description;
    }

    /** As a variant names it, and as the calibration's id: {@code seam:NAME}. */
    public String spec() {
        return PREFIX + label;
    }

    /** Whether it distorts the command rather than the observation. */
    public boolean actsOnCommand() {
        return make.apply(null) instanceof CommandDistortion;
    }

    /** Its distortion for one run, drawing (if it draws at all) from the run's stream {@code seam.NAME}. */
    Distortion distortion(RandomStreams streams) {
        return make.apply(streams.stream("seam." + label));
    }

    /** Whether {@code spec} names seam faults ({@code seam:NAME} or {@code seam:ALL}). */
    public static boolean names(String spec) {
        return spec.strip().startsWith(PREFIX);
    }

    /**
     * The seam faults {@code spec} names: {@code seam:NAME} or {@code seam:ALL} (in catalogue order).
     *
     * @throws IllegalArgumentException naming the spec and the catalogue's names
     */
    public static List<SeamFault> parse(String spec) {
        String s = spec.strip();
        if (!s.startsWith(PREFIX)) {
            throw new IllegalArgumentException("a seam fault is seam:NAME or seam:ALL, not '" + s + "'");
        }
        String name = s.substring(PREFIX.length()).strip();
        if (name.equals("ALL")) {
            return List.of(values());
        }
        return Arrays.stream(values()).filter(f -> f.label.equals(name.toLowerCase(Locale.ROOT))).findFirst()
                .map(List::of).orElseThrow(() -> new IllegalArgumentException("there is no seam fault '" + name
                        + "'; the seam faults are " + names() + " (or seam:ALL for all of them)"));
    }

    /** The seam faults a comma-separated list of specs names, each once, in catalogue order. */
    public static Set<SeamFault> parseSet(String specs) {
        Set<SeamFault> all = EnumSet.noneOf(SeamFault.class);
        List<String> parts = new ArrayList<>(Arrays.asList(specs.split(",")));
        for (String p : parts) {
            all.addAll(parse(p.strip().startsWith(PREFIX) ? p : PREFIX + p.strip()));
        }
        return all;
    }

    private static String names() {
        return Arrays.stream(values()).map(f -> f.label).collect(Collectors.joining(", "));
    }
}
