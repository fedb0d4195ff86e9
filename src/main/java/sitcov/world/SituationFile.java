package sitcov.world;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
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

    private SituationFile() {
    }

    /** The file's text for {@code map}. */
    public static String format(WorldMap map) {
        return SituationWriter.format(map);
    }

    /** Writes {@code map} to {@code file} atomically: a half-written file never replaces a good one. */
    public static void write(WorldMap map, Path file) throws IOException {
        Path absolute = file.toAbsolutePath();
        Path folder = absolute.getParent();
        Path temp = Files.createTempFile(folder, "." + absolute.getFileName(), ".tmp");
        if (Files.getFileStore(temp).supportsFileAttributeView("posix")) {
            // a situation file is for sharing: readable by others, as a file a shell made would be
            Files.setPosixFilePermissions(temp, java.nio.file.attribute.PosixFilePermissions.fromString("rw-r--r--"));
        }
        try {
            Files.writeString(temp, format(map), StandardCharsets.UTF_8);
            Files.move(temp, absolute, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /** Reads a situation file; a malformed one is refused with its name, line and what was expected. */
    public static WorldMap read(Path file) throws IOException, SituationFormatException {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (java.nio.charset.MalformedInputException e) {
            throw new SituationFormatException(file.toString(), 0, "not a text file (expected UTF-8 text)");
        }
        return parse(lines, file.toString());
    }

    /** Parses the lines of a situation file; {@code source} names it in error messages. */
    public static WorldMap parse(List<String> lines, String source) throws SituationFormatException {
        return new SituationParser(source).parse(lines);
    }
}
