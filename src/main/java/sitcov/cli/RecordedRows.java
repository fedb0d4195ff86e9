package sitcov.cli;

import java.nio.file.Path;
import java.util.Optional;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.MapId;
import sitcov.judge.Variant;
import sitcov.judge.FaultOutcome;
import sitcov.judge.JudgedMap;
import sitcov.judge.RunSummary;
import sitcov.results.ResultsFolder;
import sitcov.results.ResultsRows;

/** What the commands that run a recorded row again ({@code replay}, {@code export}) check before they trust it. */
final class RecordedRows {
    private RecordedRows() {
    }

    /** Whether the row's runs are the builtin car's as the folder's experiment ran it (with its seeded fault, if any). */
    static boolean ofTheBuiltinCar(ResultsRows.Row row) {
        return row.config().controller().equals(ExperimentConfig.BUILTIN)
                && row.variant().filter(v -> v instanceof Variant.Controller).isEmpty();
    }

    /** Refuses a row of a folder that tested another controller: these commands run the builtin car. */
    static void refuseOtherController(String command, Path folder, ResultsRows.Row row) throws UsageException {
        java.util.Optional<Variant> seam = row.variant().filter(v -> v instanceof Variant.Seam);
        if (seam.isPresent()) {
            throw new UsageException(command + ": row " + row.number() + " of " + folder + " ran " + seam.get().spec()
                    + ", a seam fault of the controller " + row.config().controller() + ", and " + command + " runs the"
                    + " builtin car without seam faults; pick a row of the reference or of another variant.");
        }
        java.util.Optional<Variant> other = row.variant().filter(v -> v instanceof Variant.Controller);
        if (ofTheBuiltinCar(row)) {
            return;
        }
        // the row's own controller: a variant that is a controller of its own, else the reference (with its seeded fault)
        String controller = other.map(Variant::spec).orElse(row.config().controller());
        String faults = row.fault().map(f -> " --faults " + f.id()).orElse("");
        String map = row.map().map() instanceof MapId.Situation s
                ? "--load " + ResultsFolder.situation(folder, s.name()) : "--seed " + row.map().externalSeed();
        throw new UsageException(command + ": row " + row.number() + " of " + folder + " ran the controller " + controller
                + ", and " + command + " runs the builtin car; run its map with that controller: 'simulate " + map
                + " --internal-seed " + row.map().internalSeed() + faults + " --controller \"" + controller
                + "\" --png FILE'");
    }

    /** A run's summary as people read it: "TARGET_REACHED after 750 ticks, accidents: LEAVEROAD 1". */
    static String words(RunSummary run) {
        java.util.List<String> counts = new java.util.ArrayList<>();
        for (sitcov.oracle.AccidentType t : sitcov.oracle.AccidentType.values()) {
            long n = run.accidents().get(t.ordinal());
            if (n > 0) {
                counts.add(t.name() + " " + n);
            }
        }
        return run.outcome() + " after " + run.ticks() + " ticks, " + (counts.isEmpty() ? "no accident"
                : "accidents: " + String.join(", ", counts));
    }

    static String words(FaultOutcome o) {
        return o.detection() + o.newAccident().map(t -> " by " + t).orElse("") + " (" + (o.reached() ? "reached" : "not reached")
                + ", " + (o.effective() ? "effective from tick " + o.firstEffectiveTick() : "no effect") + "; the faulty run "
                + words(o.run()) + ")";
    }

    /** How the row, judged again, differs from what {@code runs.csv} recorded; empty when it is the same. */
    static Optional<String> differences(ResultsRows.Row row, JudgedMap judged) {
        RunSummary recorded = row.map().faultFree();
        RunSummary replayed = RunSummary.of(judged.faultFree());
        if (!recorded.agrees(replayed)) {
            return Optional.of("the fault-free run was recorded as " + unlike(words(recorded), words(replayed)));
        }
        if (row.outcome().isPresent()) {
            FaultOutcome was = row.outcome().get();
            FaultOutcome now = FaultOutcome.of(judged.verdicts().get(0));
            if (!was.agrees(now)) {
                return Optional.of("fault " + was.variant().id() + " was recorded as " + unlike(words(was), words(now)));
            }
        }
        return Optional.empty();
    }

    /** "X, it now gives Y"; where the words agree, what else differs: the margins they leave out. */
    private static String unlike(String was, String now) {
        return was + ", it now gives " + now + (was.equals(now) ? ", with other near misses or robustness (runs.csv's"
                + " near_* and rho_* columns)" : "");
    }
}
