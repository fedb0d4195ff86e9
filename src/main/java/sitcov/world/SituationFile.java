package sitcov.world;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Situation files: a plain-text, versioned, line-oriented description of a whole {@link WorldMap}.
 * Reading a written file gives back an equal map, so a situation can be replayed without the
 * generator. Numbers are written in Java's shortest round-trip form; {@code #} starts a comment.
 *
 * <pre>
 * sitcov-situation 1
 * seed 42
 * generation JUNCTION_ATTEMPTS PARKED_CARS_REQUESTED MOVING_CARS_REQUESTED
 * road ID AXIS CENTRE FROM TO
 * junction ID X Y ARM_NORTH ARM_EAST ARM_SOUTH ARM_WEST
 * parked-car ID ROAD_ID X Y AXIS
 * target X Y ROAD_ID
 * car-start X Y HEADING
 * moving-car X Y HEADING
 * omission layout|moving-cars ELEMENT: REASON
 * end
 * </pre>
 */
public final class SituationFile {
    public static final String MAGIC = "sitcov-situation";
    public static final int VERSION = 1;
    /** Far more than the generator makes (5 to 24 junction attempts, at most 9 parked and 19 moving cars). */
    public static final int MAX_ROADS = 100;
    public static final int MAX_JUNCTIONS = 200;
    public static final int MAX_CARS = 200;
    /** Every element lies in the 200 x 100 m world; a coordinate this far out is a typing slip. */
    public static final double MAX_COORDINATE = 1000;
    public static final int MAX_BYTES = 1 << 20;

    private SituationFile() {
    }

    /** The file's text for {@code map}. */
    public static String format(WorldMap map) {
        return SituationWriter.format(map);
    }

    /**
     * Reads a situation file; one that is malformed or breaks a rule of the world
     * (src/main/java/sitcov/cli/README.md, "Maps and situation files") is
     * refused with its name, the line and what was expected there or the rule broken.
     */
    public static WorldMap read(Path file) throws IOException, SituationFormatException {
        byte[] bytes;
        try (java.io.InputStream in = Files.newInputStream(file)) {
            // read at most one byte past the cap: a device or a huge file is refused, never read whole
            bytes = in.readNBytes(MAX_BYTES + 1);
        }
        if (bytes.length > MAX_BYTES) {
            throw new SituationFormatException(file.toString(), 0, "larger than " + (MAX_BYTES >> 20)
                    + " MiB: a situation file has at most " + MAX_ROADS + " roads, " + MAX_JUNCTIONS + " junctions and "
                    + MAX_CARS + " parked and moving cars each");
        }
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder().decode(java.nio.ByteBuffer.wrap(bytes)).toString();
        } catch (java.nio.charset.CharacterCodingException e) {
            throw new SituationFormatException(file.toString(), 0, "not UTF-8 text (is this a situation file?)");
        }
        return parse(text.lines().toList(), file.toString());
    }

    /** Parses the lines of a situation file; {@code source} names it in error messages. */
    public static WorldMap parse(List<String> lines, String source) throws SituationFormatException {
        return new SituationParser(source).parse(lines);
    }
}
