package sitcov.judge;

import java.util.List;
import sitcov.oracle.Accident;
import sitcov.oracle.RunResult;

/**
 * One variant of a controller against its reference on one map and seeds: both runs, the accidents
 * the variant has that the reference does not ({@code fresh}: it fails where the reference did not),
 * and those the reference has that the variant does not ({@code fixed}).
 */
public record VersionVerdict(int variant, RunResult reference, RunResult run, List<Accident> fresh,
                             List<Accident> fixed) {
    public VersionVerdict {
        fresh = List.copyOf(fresh);
        fixed = List.copyOf(fixed);
    }

    /** The variant fails where the reference did not. */
    public boolean regressed() {
        return !fresh.isEmpty();
    }

    /** The reference failed where the variant does not. */
    public boolean improved() {
        return !fixed.isEmpty();
    }
}
