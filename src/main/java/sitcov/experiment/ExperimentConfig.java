package sitcov.experiment;

import java.util.Set;
import sitcov.coverage.GridDefinition;
import sitcov.faults.Fault;

/**
 * One comparison experiment: the coverage-filter driver looks at {@code candidates} candidate maps
 * per replication; the random driver then gets the same budget of the given kind.
 */
public record ExperimentConfig(String name, long masterSeed, int candidates, int replications, Set<Fault> faults,
                               BudgetKind budget, GridDefinition grid) {
    public ExperimentConfig {
        if (candidates < 1 || replications < 1) {
            throw new IllegalArgumentException("an experiment needs at least one candidate and one replication");
        }
        faults = Set.copyOf(faults);
    }
}
