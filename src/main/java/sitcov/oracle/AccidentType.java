package sitcov.oracle;

import java.util.Locale;

/**
 * The kinds of accident the oracle detects (faults/README.md, "The car under test, the traffic and the oracle").
 * Each carries its names: {@link #column()} in runs.csv, {@link #word()} in the calibration table
 * (one word, as that table's cells are separated by spaces) and {@link #label()} in the pictures' captions.
 */
public enum AccidentType {
    /** The car's footprint overlaps a parked car. */
    CLASHWITHOBSTACLE("obstacle", "obstacle"),
    /** The car's footprint overlaps a moving car, and the blame rules put it at fault. */
    CLASHWITHOTHERCAR("car", "other car"),
    /** Some part of the car's footprint is off the road surface. */
    LEAVEROAD("leaveroad", "off road"),
    /** The car is over the centre line without overtaking or turning through a junction. */
    CROSSCENTRELINE("centreline", "centre line"),
    /** The Target was not reached in 5000 ticks. */
    TIMEOUT("timeout", "timeout");

    private final String word;
    private final String label;

    AccidentType(String word, String label) {
        this.word = word;
        this.label = label;
    }

    /** The name of its robustness ρ's column in runs.csv. */
    public String robustnessColumn() {
        return "rho_" + column();
    }

    /** The name of its count's column in runs.csv. */
    public String column() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** Its short name in one word, as in the calibration table of {@code faults --calibrate}. */
    public String word() {
        return word;
    }

    /** Its short name in a caption, where a picture has no room for the whole name. */
    public String label() {
        return label;
    }
}
