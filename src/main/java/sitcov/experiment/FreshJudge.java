package sitcov.experiment;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import sitcov.judge.FaultOutcome;
import sitcov.judge.JudgedMap;
import sitcov.judge.MapRunner;
import sitcov.judge.RunSummary;
import sitcov.vehicles.CommandLog;
import sitcov.world.WorldMap;

/**
 * Judges a session's map now: fault-free and once per fault. A map another driver of the replication
 * judged already is taken from it (the same map and seeds run the same) and charged at the time it took.
 */
final class FreshJudge implements SessionJudge {
    private final ExperimentRunner host;
    private final int replication;
    private final String driver;
    private final SharedMaps shared;
    private final DriverClock clock;

    FreshJudge(ExperimentRunner host, int replication, String driver, SharedMaps shared, DriverClock clock) {
        this.host = host;
        this.replication = replication;
        this.driver = driver;
        this.shared = shared;
        this.clock = clock;
    }

    @Override
    public Judgement judge(Request r) {
        long start = clock.now();
        long internal = SeedPlan.internalSeed(host.config().masterSeed(), r.id());
        SharedMaps.Judged judgedBefore = shared.judged(r.id());
        WorldMap world;
        JudgedMap judged;
        Map<Integer, CommandLog> recordings = null;
        if (judgedBefore != null) {
            world = judgedBefore.world();
            judged = judgedBefore.judged();
            recordings = judgedBefore.recordings();
        } else {
            world = r.map().get();
            judged = MapRunner.judgeVariants(world, internal, host.variants(), host.config().faultyRuns(),
                    host.controllers().forThisThread(), host::variantController);
        }
        List<Double> values = new ArrayList<>(r.criteria().length);
        for (double v : r.criteria()) {
            values.add(v);
        }
        MapRun run = new MapRun(replication, driver, r.index(), r.candidate(), r.id(), world.seed(), internal, r.cell(),
                values, RunSummary.of(judged.faultFree()), judged.verdicts().stream().map(FaultOutcome::of).toList());
        if (recordings == null) {
            recordings = recordings(run, judged);
        }
        long nanos = clock.now() - start;
        if (judgedBefore != null) {
            clock.judged(judgedBefore.nanos(), judgedBefore.nanos() - nanos);
            nanos = judgedBefore.nanos();
        } else {
            shared.keep(r.id(), new SharedMaps.Judged(world, judged.withoutCommands(), nanos, recordings));
            clock.judged(nanos, 0);
        }
        return new Judgement(run, false, nanos, clock.elapsed(), recordings);
    }

    /** The commands of the map's runs a folder records: its failures and findings, or every run when asked. */
    private Map<Integer, CommandLog> recordings(MapRun run, JudgedMap judged) {
        boolean[] kept = run.recorded();
        Map<Integer, CommandLog> recordings = new HashMap<>();
        for (int i = 0; i < kept.length; i++) {
            if (kept[i] || host.recordsAll()) {
                recordings.put(i, judged.commands().get(i));
            }
        }
        return recordings;
    }
}
