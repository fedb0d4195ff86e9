package sitcov.analysis;

import java.util.List;
import java.util.Optional;
import sitcov.experiment.CampaignTarget;
import sitcov.experiment.DriverRun;
import sitcov.experiment.MapRun;
import sitcov.experiment.StopReason;
import sitcov.oracle.Failure;
import sitcov.stats.KaplanMeier;

/**
 * One trial of one driver in the campaign of one target (experiments/README.md, "Campaigns: falsifying one version"):
 * falsified when a map it ran falsified the target (its variant found by the differential oracle, or its
 * requirement violated by the reference) within the budget. {@code ticksToFailure} is the ticks spent up to and
 * including that map, or all the ticks spent, and {@code mapsRun} the maps; {@code survivalTicks} is what the
 * survival analysis uses: the ticks to failure of a falsified trial, else the ticks spent capped at the budget
 * (censored) — a map that falsified the target only past the budget does not count, so no driver gains from
 * overshooting it.
 */
public record CampaignTrial(CampaignTarget target, String driver, int trial, long campaignSeed, String streamLabel,
                            boolean falsified, long ticksToFailure, long survivalTicks, int mapsRun, StopReason stop,
                            Optional<FoundMap> found, Optional<Failure> accident) {
    /**
     * The map that falsified the target, as campaign.csv keeps it: enough to replay it ({@code map} is its
     * {@link sitcov.experiment.MapId}'s text) and to count it as a distinct failure.
     */
    public record FoundMap(int mapIndex, String map, long externalSeed, long internalSeed, int cell) {
        static FoundMap of(MapRun run) {
            return new FoundMap(run.mapIndex(), run.map().text(), run.externalSeed(), run.internalSeed(), run.cell());
        }
    }

    /** The trial as {@code run} (one driver's share of replication {@code trial}) recorded it. */
    public static CampaignTrial of(CampaignTarget target, int trial, long campaignSeed, String streamLabel, long tickBudget,
                                   DriverRun run) {
        long spent = 0;
        int maps = 0;
        for (MapRun m : run.maps()) {
            spent += m.ticks();
            maps++;
            if (target.falsifiedOn(m)) {
                boolean within = spent <= tickBudget;
                return new CampaignTrial(target, run.driver(), trial, campaignSeed, streamLabel, within, spent,
                        within ? spent : tickBudget, maps, run.spend().stoppedBy(), Optional.of(FoundMap.of(m)), target.failureOn(m));
            }
        }
        return new CampaignTrial(target, run.driver(), trial, campaignSeed, streamLabel, false, spent,
                Math.min(spent, tickBudget), maps, run.spend().stoppedBy(), Optional.empty(), Optional.empty());
    }

    /** The trial as the survival analysis sees it. */
    public KaplanMeier.Observation observation() {
        return new KaplanMeier.Observation(survivalTicks, falsified);
    }

    /** The failure the trial found, as a distinct failure counts it: its cell and accident type; empty if not falsified. */
    public Optional<String> failure() {
        if (!falsified) {
            return Optional.empty();
        }
        return Optional.of(found.orElseThrow().cell() + "×" + accident.map(Failure::column).orElse("?"));
    }

    static List<KaplanMeier.Observation> observations(List<CampaignTrial> trials) {
        return trials.stream().map(CampaignTrial::observation).toList();
    }
}
