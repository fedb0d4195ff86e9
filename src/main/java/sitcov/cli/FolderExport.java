package sitcov.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import sitcov.builtin.BuiltinCar;
import sitcov.export.AsamFrame;
import sitcov.export.OpenScenario;
import sitcov.export.RunRecording;
import sitcov.export.ScenarioVersion;
import sitcov.faults.Fault;
import sitcov.experiment.MapId;
import sitcov.judge.FaultVerdict;
import sitcov.judge.JudgedMap;
import sitcov.judge.MapRunner;
import sitcov.oracle.Accident;
import sitcov.judge.RunObserver;
import sitcov.judge.Variant;
import sitcov.recording.FolderRecordings;
import sitcov.recording.Recording;
import sitcov.recording.RecordingFile;
import sitcov.results.ResultsRows;
import sitcov.vehicles.CommandLog;
import sitcov.world.WorldMap;

/**
 * {@code export RESULTS --row N} and {@code export RESULTS --found}: runs of a results folder, driven
 * from the commands it kept (or, where it kept none, run again with the builtin car), checked against
 * {@code runs.csv} as replays are, and written as recordings beside their map, the accident that found
 * a fault marked.
 */
final class FolderExport {
    private static final String INDEX_HEADER = "row,replication,driver,map_index,external_seed,internal_seed,fault,"
            + "new_accident,tick,seconds,x,y,road_file,situation_file,run_file";

    /** A found run is recorded to 5 s after the accident that found it: what follows shows nothing more. */
    static final long AFTER_FAILURE_TICKS = 25;

    private FolderExport() {
    }

    /** {@code err} takes the progress of --found, which judges every run that found a fault again. */
    static ExportCommand.Plan plan(Options options, ScenarioVersion version, java.io.PrintStream err) throws UsageException {
        if (options.positional().size() != 1 || options.has("--seed") || options.has("--load")
                || options.has("--record") || options.has("--internal-seed")) {
            throw new UsageException("export: name one results folder with --row N or --found; maps (--seed, --load)"
                    + " are exported without a folder.");
        }
        if (options.has("--row") == options.has("--found")) {
            throw new UsageException("export: with a results folder, give --row N (one recorded run) or --found"
                    + " (every run that found a fault).");
        }
        Path folder = Path.of(options.positional().get(0));
        try {
            return options.has("--row") ? row(folder, options, version) : found(folder, options, version, err);
        } catch (IOException | IllegalArgumentException e) {
            throw new UsageException("export: " + e.getMessage() + ".");
        }
    }

    private static ExportCommand.Plan row(Path folder, Options options, ScenarioVersion version)
            throws UsageException, IOException {
        if (options.has("--fault")) {
            throw new UsageException("export: --row N names the run whole, its fault included; drop --fault.");
        }
        int number = options.count("--row", 1, Integer.MAX_VALUE).orElseThrow();
        ResultsRows.Row row = ResultsRows.row(folder, number);
        WorldMap map = ResultsRows.worldMap(folder, row.map());
        String base = "row-" + number;
        List<ExportCommand.Planned> files = new ArrayList<>(ExportCommand.mapFiles(base, map, version));
        if (FolderRecordings.has(folder, row)) {
            Optional<Accident> found = replayed(folder, row, map).verdict().flatMap(FaultVerdict::newAccident);
            files.add(fromRecording(base + "-run.xosc", base + ".xodr", folder, row, map, false, Long.MAX_VALUE, found,
                    version));
            if (row.variant().isPresent()) {
                files.add(fromRecording(base + "-run-fault-free.xosc", base + ".xodr", folder, row, map, true,
                        Long.MAX_VALUE, Optional.empty(), version));
            }
            return new ExportCommand.Plan(files, to -> "Exported row " + number + " of " + folder + ", replayed from its"
                    + " recordings, to " + to + ": " + String.join(", ", files.stream().map(ExportCommand.Planned::name)
                    .toList()) + ".");
        }
        RecordedRows.refuseOtherController("export", folder, row);
        Set<Fault> faults = row.fault().map(Set::of).orElse(Set.of());
        Optional<Accident> found = checked(row, map).verdicts().stream().findFirst().flatMap(FaultVerdict::newAccident);
        files.add(ExportCommand.recording(base + "-run.xosc", base + ".xodr", map, row.map().internalSeed(), faults,
                found, version));
        if (row.fault().isPresent()) {
            files.add(ExportCommand.recording(base + "-run-fault-free.xosc", base + ".xodr", map,
                    row.map().internalSeed(), Set.of(), Optional.empty(), version));
        }
        return new ExportCommand.Plan(files, to -> "Exported row " + number + " of " + folder + " to " + to + ": "
                + String.join(", ", files.stream().map(ExportCommand.Planned::name).toList()) + ".");
    }

    private static ExportCommand.Plan found(Path folder, Options options, ScenarioVersion version,
            java.io.PrintStream err) throws UsageException, IOException {
        List<ResultsRows.Row> found = foundRows(folder, options);
        List<String> index = new ArrayList<>(List.of(INDEX_HEADER));
        Progress progress = new Progress(err, "export: found runs judged again", found.size(),
                err == System.err && System.console() != null, System::nanoTime);
        Shared shared = new Shared();
        for (ResultsRows.Row row : found) {
            WorldMap map = shared.map(folder, row, version);
            String road = mapName(row.map().map()) + ".xodr";
            Optional<Integer> variant = row.variant().map(Variant::id);
            FaultVerdict verdict;
            String runFile;
            // every row is judged again before anything is written: a folder of another sitcov leaves nothing behind
            if (FolderRecordings.has(folder, row)) {
                verdict = replayed(folder, row, map).verdict().orElseThrow();
                long until = verdict.newAccident().map(a -> a.tick() + AFTER_FAILURE_TICKS).orElse(Long.MAX_VALUE);
                Recording r = RecordingFile.read(FolderRecordings.file(folder, FolderRecordings.key(row, false)));
                runFile = shared.run(new SameRun(row.map().map(), r.internalSeed(), variant, Math.min(until, r.stopAfter()),
                        Optional.of(r.commands())), row, name -> fromRecording(name, road, r, row, map, false, until,
                        verdict.newAccident(), version));
            } else {
                RecordedRows.refuseOtherController("export", folder, row);
                verdict = checked(row, map).verdicts().get(0);
                Accident failure = verdict.newAccident().orElseThrow();
                long until = failure.tick() + AFTER_FAILURE_TICKS;
                runFile = shared.run(new SameRun(row.map().map(), row.map().internalSeed(), variant, until, Optional.empty()),
                        row, name -> new ExportCommand.Planned(name, () -> OpenScenario.recording(RunRecording.of(map,
                                row.map().internalSeed(), Set.of(row.fault().orElseThrow()), BuiltinCar.FACTORY)
                                .until(until).cutAfterStandingFor(AFTER_FAILURE_TICKS), Optional.of(failure), road, version)));
            }
            index.add(indexLine(row, verdict, mapName(row.map().map()), runFile));
            progress.done(index.size() - 1);
        }
        List<ExportCommand.Planned> files = new ArrayList<>(shared.files);
        files.add(new ExportCommand.Planned(ExportCommand.INDEX, () -> String.join("\n", index) + "\n"));
        int maps = shared.maps.size();
        int runs = shared.runs.size();
        return new ExportCommand.Plan(files, to -> "Exported the " + found.size() + " runs of " + folder
                + " that found a fault to " + to + ": " + maps + (maps == 1 ? " map" : " maps") + " (roads and situation)"
                + " and " + runs + " faulty " + (runs == 1 ? "run" : "runs") + " (recorded to 5 s after the accident that"
                + " found it; rows that ran the same run share its file); " + ExportCommand.INDEX + " names each row's files.");
    }

    /** What --found plans as its rows come: a road file and a situation a map, a file a distinct run. */
    private static final class Shared {
        private final List<ExportCommand.Planned> files = new ArrayList<>();
        private final Map<MapId, WorldMap> maps = new HashMap<>();
        private final Map<SameRun, String> runs = new HashMap<>();

        /** The row's map, its two files planned the first time one of its rows comes. */
        WorldMap map(Path folder, ResultsRows.Row row, ScenarioVersion version) throws IOException {
            WorldMap map = maps.get(row.map().map());
            if (map == null) {
                map = ResultsRows.worldMap(folder, row.map());
                maps.put(row.map().map(), map);
                files.addAll(ExportCommand.mapFiles(mapName(row.map().map()), map, version));
            }
            return map;
        }

        /** The file of the run {@code same}: planned by {@code plan} under {@code row}'s name the first time. */
        String run(SameRun same, ResultsRows.Row row, java.util.function.Function<String, ExportCommand.Planned> plan) {
            return runs.computeIfAbsent(same, s -> {
                String name = "row-" + row.number() + "-run.xosc";
                files.add(plan.apply(name));
                return name;
            });
        }
    }

    /** The rows whose fault was found (with --fault, those faults only); none is a mistake. */
    private static List<ResultsRows.Row> foundRows(Path folder, Options options) throws UsageException, IOException {
        Optional<Set<Fault>> only = options.faults("--fault");
        List<ResultsRows.Row> rows = ResultsRows.all(folder);
        if (only.isPresent() && !rows.isEmpty()) {
            for (Fault f : only.get()) {
                if (!rows.get(0).config().faults().contains(f)) {
                    throw new UsageException("export: the experiment in " + folder + " did not seed fault " + f.id()
                            + "; its faults are " + rows.get(0).config().faults().stream().map(Fault::id).sorted().toList()
                            + ".");
                }
            }
        }
        List<ResultsRows.Row> found = rows.stream().filter(r -> r.outcome().isPresent()
                && r.outcome().get().detection().found()
                && (only.isEmpty() || only.get().contains(r.fault().orElseThrow()))).toList();
        if (found.isEmpty()) {
            throw new UsageException("export: no run in " + folder + " found " + only.map(f -> "fault "
                    + f.stream().map(Fault::id).sorted().toList()).orElse("a fault") + "; there is nothing to export.");
        }
        return found;
    }

    /**
     * What makes two found rows' exported runs the same document: the map, the seed, the variant, the tick the
     * recording stops after and, for a run replayed from its recording, the commands it carried out.
     */
    private record SameRun(MapId map, long internalSeed, Optional<Integer> variant, long until,
                           Optional<CommandLog> commands) {
    }

    /** The base name of a map's road file and situation: as {@code export --seed} names a generated map. */
    static String mapName(MapId map) {
        return map instanceof MapId.Situation s ? "situation-" + s.name() : "map-" + ((MapId.Seeded) map).externalSeed();
    }

    /** The row replayed from its recordings; it must give what runs.csv recorded, or the export stops. */
    private static FolderRecordings.Replayed replayed(Path folder, ResultsRows.Row row, WorldMap map) throws IOException {
        try {
            return FolderRecordings.replay(folder, row, map, RunObserver.NONE, RunObserver.NONE).orElseThrow();
        } catch (IllegalArgumentException e) {
            throw new ExportCommand.RowMismatch(e.getMessage());
        }
    }

    /**
     * The row's own run ({@code reference}: its reference's), replayed from its recording to the end of tick
     * {@code until} at most (a controller failure ends it where it failed; a run the experiment stopped at its
     * verdict, there), as an OpenSCENARIO recording; {@code found} is the accident that found its fault.
     */
    private static ExportCommand.Planned fromRecording(String name, String roadFile, Path folder, ResultsRows.Row row,
                                                       WorldMap map, boolean reference, long until,
                                                       Optional<Accident> found, ScenarioVersion version)
            throws IOException {
        Recording r = RecordingFile.read(FolderRecordings.file(folder, FolderRecordings.key(row, reference)));
        return fromRecording(name, roadFile, r, row, map, reference, until, found, version);
    }

    private static ExportCommand.Planned fromRecording(String name, String roadFile, Recording r, ResultsRows.Row row,
                                                       WorldMap map, boolean reference, long until,
                                                       Optional<Accident> found, ScenarioVersion version) {
        Set<Fault> faults = reference ? Set.of() : row.fault().map(Set::of).orElse(Set.of());
        return new ExportCommand.Planned(name, () -> OpenScenario.recording(foundPart(RunRecording.replayed(map,
                r.internalSeed(), r.commands(), r.stopAfter(), faults), until), found, roadFile, version));
    }

    /**
     * The part of a run an export shows: to the end of tick {@code until}; a found run ({@code until} short of
     * the end), also no more than 5 s after its car stopped for good, as a run that times out standing does.
     */
    private static RunRecording foundPart(RunRecording run, long until) {
        RunRecording part = run.until(until);
        return until == Long.MAX_VALUE ? part : part.cutAfterStandingFor(AFTER_FAILURE_TICKS);
    }

    /** The row judged again; it must give what runs.csv recorded, or the export stops. */
    private static JudgedMap checked(ResultsRows.Row row, WorldMap map) {
        JudgedMap judged = MapRunner.judge(map, row.map().internalSeed(), row.fault().stream().toList(),
                row.config().faultyRuns(), BuiltinCar.FACTORY);
        Optional<String> differs = RecordedRows.differences(row, judged);
        if (differs.isPresent()) {
            throw new ExportCommand.RowMismatch("row " + row.number() + " does not run again as recorded: " + differs.get()
                    + ". Was the folder written by another version of sitcov? (see its manifest)");
        }
        return judged;
    }

    /** The row's line of index.csv; a controller's failure has no place, so its x and y are left empty. */
    private static String indexLine(ResultsRows.Row row, FaultVerdict verdict, String base, String runFile) {
        Optional<Accident> accident = verdict.newAccident();
        long tick = accident.map(Accident::tick).orElse(verdict.faultyRun().ticks() - 1);
        String what = accident.map(a -> a.type().name()).orElse(verdict.newFailure().map(Object::toString).orElse(""));
        return String.join(",", List.of(Integer.toString(row.number()), Integer.toString(row.map().replication()),
                row.map().driver(), Integer.toString(row.map().mapIndex()), Long.toString(row.map().externalSeed()),
                Long.toString(row.map().internalSeed()), Integer.toString(verdict.variant().id()), what,
                Long.toString(tick), String.format(java.util.Locale.ROOT, "%.1f", AsamFrame.seconds(tick)),
                accident.map(a -> String.format(java.util.Locale.ROOT, "%.3f", AsamFrame.x(a.x()))).orElse(""),
                accident.map(a -> String.format(java.util.Locale.ROOT, "%.3f", AsamFrame.y(a.y()))).orElse(""),
                base + ".xodr", base + ".xosc", runFile));
    }
}
