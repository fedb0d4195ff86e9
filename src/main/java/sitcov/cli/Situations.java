package sitcov.cli;

import java.io.IOException;
import java.nio.file.Path;
import sitcov.results.IoReason;
import sitcov.world.SituationFile;
import sitcov.world.SituationFormatException;
import sitcov.world.WorldMap;

/** Situation files as commands read them: a file that is malformed or breaks the world's rules is a user's mistake. */
final class Situations {
    private Situations() {
    }

    static WorldMap load(String command, Path file) throws UsageException {
        try {
            return SituationFile.read(file);
        } catch (SituationFormatException e) {
            throw new UsageException(command + ": " + e.getMessage());
        } catch (IOException e) {
            throw new UsageException(command + ": cannot read " + file + ": " + sitcov.results.IoReason.of(e, file) + ".");
        }
    }

    /** A situation a command will run: it must have a Target and a car start. */
    static WorldMap loadRunnable(String command, Path file) throws UsageException {
        WorldMap map = load(command, file);
        if (map.layout().target().isEmpty() || map.layout().carStart().isEmpty()) {
            throw new UsageException(command + ": " + file + " has no " + (map.layout().target().isEmpty()
                    ? "'target X Y ROAD_ID'" : "'car-start X Y HEADING'") + " line; a run needs a Target and a car"
                    + " start: add the line, or describe the map with 'map --load'.");
        }
        return map;
    }
}
