package sitcov.results;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.Journal;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.judge.Variant;
import sitcov.judge.FaultOutcome;
import sitcov.world.MapGenerator;
import sitcov.world.SituationFile;
import sitcov.world.WorldMap;

/**
 * The runs a results folder recorded, found again: by the number of a row of {@code runs.csv}
 * (1 is the first row under the header; each map's block is its fault-free row, then one row per
 * fault in id order), or by replication, driver, map index and fault.
 */
public final class ResultsRows {
    /** One recorded run: the experiment, the judged map, and the variant of the row (empty: the reference's row). */
    public record Row(ExperimentConfig config, MapRun map, Optional<Variant> variant, int number) {
        /** The variant's recorded outcome on this map. */
        public Optional<FaultOutcome> outcome() {
            return variant.flatMap(f -> map.faults().stream().filter(o -> o.variant().equals(f)).findFirst());
        }

        /** The seeded fault of the row, when its variant is one. */
        public Optional<sitcov.faults.Fault> fault() {
            return variant.filter(v -> v instanceof Variant.Seeded).map(v -> ((Variant.Seeded) v).fault());
        }
    }

    private ResultsRows() {
    }

    public static Row row(Path folder, int number) throws IOException {
        Manifest manifest = Manifest.read(folder);
        ExperimentConfig config = manifest.config();
        List<Journal.Entry> maps = JournalFiles.inOrder(config, JournalFiles.read(folder, manifest));
        int perMap = 1 + config.variants().size();
        if (number < 1 || number > maps.size() * perMap) {
            throw new IllegalArgumentException("runs.csv of " + folder + " has rows 1.." + maps.size() * perMap
                    + " under its header, not " + number);
        }
        int slot = (number - 1) % perMap;
        MapRun map = maps.get((number - 1) / perMap).run();
        return new Row(config, map, slot == 0 ? Optional.empty() : Optional.of(config.variants().get(slot - 1)), number);
    }

    /** Every row of {@code runs.csv}, in its order. */
    public static List<Row> all(Path folder) throws IOException {
        Manifest manifest = Manifest.read(folder);
        ExperimentConfig config = manifest.config();
        List<Journal.Entry> maps = JournalFiles.inOrder(config, JournalFiles.read(folder, manifest));
        List<Row> rows = new ArrayList<>();
        for (Journal.Entry map : maps) {
            rows.add(new Row(config, map.run(), Optional.empty(), rows.size() + 1));
            for (Variant f : config.variants()) {
                rows.add(new Row(config, map.run(), Optional.of(f), rows.size() + 1));
            }
        }
        return rows;
    }

    /** The row of {@code driver}'s map {@code mapIndex} in {@code replication}: the reference's, or the variant {@code variantId}'s. */
    public static Row find(Path folder, int replication, String driver, int mapIndex, Optional<Integer> variantId)
            throws IOException {
        Manifest manifest = Manifest.read(folder);
        ExperimentConfig config = manifest.config();
        List<Journal.Entry> maps = JournalFiles.inOrder(config, JournalFiles.read(folder, manifest));
        Optional<Variant> fault = variantId.flatMap(id -> config.variants().stream().filter(v -> v.id() == id).findFirst());
        if (variantId.isPresent() && fault.isEmpty()) {
            throw new IllegalArgumentException("the experiment in " + folder + " has no variant " + variantId.get()
                    + "; its variants are " + config.variants().stream().map(f -> Integer.toString(f.id())).toList());
        }
        int perMap = 1 + config.variants().size();
        for (int i = 0; i < maps.size(); i++) {
            MapRun m = maps.get(i).run();
            if (m.replication() == replication && m.driver().equals(driver) && m.mapIndex() == mapIndex) {
                int slot = fault.map(f -> 1 + config.variants().indexOf(f)).orElse(0);
                return new Row(config, m, fault, i * perMap + slot + 1);
            }
        }
        throw new IllegalArgumentException(folder + " has no map " + mapIndex + " of driver " + driver + " in replication "
                + replication);
    }

    /** The map a row ran: generated again from its external seed, or read from the folder's situation file. */
    public static WorldMap worldMap(Path folder, MapRun run) throws IOException {
        if (run.map() instanceof MapId.Situation s) {
            try {
                return SituationFile.read(ResultsFolder.situation(folder, s.name()));
            } catch (sitcov.world.SituationFormatException e) {
                throw new IllegalArgumentException("the situation " + s.name() + " kept in " + folder + " cannot be read: "
                        + e.getMessage());
            }
        }
        return MapGenerator.generate(((MapId.Seeded) run.map()).externalSeed());
    }
}
