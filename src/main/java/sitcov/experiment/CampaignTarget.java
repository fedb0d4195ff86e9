package sitcov.experiment;

import java.util.Locale;
import java.util.Optional;
import sitcov.judge.FaultOutcome;
import sitcov.judge.Notion;
import sitcov.judge.Requirement;
import sitcov.judge.Variant;
import sitcov.oracle.Failure;

/**
 * What one campaign of a campaign preset falsifies (experiments/README.md, "Campaigns: falsifying one version"): a
 * variant of the reference, found by the differential oracle, or one of the reference's own requirements,
 * violated by its own run. Each is its own experiment in its own sub-folder.
 */
public sealed interface CampaignTarget {
    /** The sub-folder of the campaign's folder that holds its trials. */
    String folder();

    /** Its column's name in the campaign's tables: {@code fault} or {@code requirement}. */
    String column();

    /** Its cell in that column: a variant's id or a requirement's key. */
    String key();

    /** A few words beside its key: a variant's label, what a requirement asks. */
    String label();

    /** Its name in a sentence or a figure's panel, e.g. {@code fault 17 (label)} or {@code timeout: misses the Target}. */
    String title();

    /** Its place among a campaign's targets: a variant's id, a requirement's place in {@link Requirement}'s order. */
    int order();

    /** The master seed of its trials ({@link SeedPlan}), so different targets' trials read different candidates. */
    long seed(long masterSeed);

    /** Whether a trial that judged {@code run} has falsified it. */
    boolean falsifiedOn(MapRun run);

    /** The failure that falsified it on {@code run}: the variant's first new accident, or the reference's violation. */
    Optional<Failure> failureOn(MapRun run);

    /** A variant of the reference, found where the differential oracle finds it. */
    record OfVariant(Variant variant) implements CampaignTarget {
        @Override
        public String folder() {
            return String.format(Locale.ROOT, variant instanceof Variant.Seeded ? "fault-%02d" : "variant-%02d", variant.id());
        }

        @Override
        public String column() {
            return "fault";
        }

        @Override
        public String key() {
            return Integer.toString(variant.id());
        }

        @Override
        public int order() {
            return variant.id();
        }

        @Override
        public String label() {
            return variant.label();
        }

        @Override
        public String title() {
            return "fault " + variant.id() + " (" + variant.label() + ")";
        }

        @Override
        public long seed(long masterSeed) {
            return SeedPlan.campaignSeed(masterSeed, variant.id());
        }

        @Override
        public boolean falsifiedOn(MapRun run) {
            return hit(run).isPresent();
        }

        @Override
        public Optional<Failure> failureOn(MapRun run) {
            return hit(run).flatMap(FaultOutcome::newAccident);
        }

        private Optional<FaultOutcome> hit(MapRun run) {
            return run.faults().stream().filter(f -> f.variant().equals(variant) && f.found(Notion.DIFFERENTIAL)).findFirst();
        }
    }

    /** One of the reference's own requirements, falsified where its run violates it. */
    record OfRequirement(Requirement requirement) implements CampaignTarget {
        @Override
        public String folder() {
            return "requirement-" + requirement.key();
        }

        @Override
        public String column() {
            return "requirement";
        }

        @Override
        public String key() {
            return requirement.key();
        }

        @Override
        public int order() {
            return requirement.ordinal();
        }

        @Override
        public String label() {
            return requirement.sentence();
        }

        @Override
        public String title() {
            return requirement.key() + ": " + requirement.violated();
        }

        @Override
        public long seed(long masterSeed) {
            return SeedPlan.campaignSeed(masterSeed, requirement);
        }

        @Override
        public boolean falsifiedOn(MapRun run) {
            return failureOn(run).isPresent();
        }

        @Override
        public Optional<Failure> failureOn(MapRun run) {
            return requirement.violation(run.faultFree());
        }
    }
}
