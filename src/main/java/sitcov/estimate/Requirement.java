package sitcov.estimate;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import sitcov.oracle.Failure;

/** What an estimate counts as a failing run: any failure at all, or one requirement's (an accident type, the Target, the controller). */
public sealed interface Requirement {
    /** Its name in files: {@code any}, or the failure's column name. */
    String column();

    boolean failedIn(Set<Failure> failures);

    /** Any failure of the run. */
    record Any() implements Requirement {
        @Override
        public String column() {
            return "any";
        }

        @Override
        public boolean failedIn(Set<Failure> failures) {
            return !failures.isEmpty();
        }
    }

    /** The requirement that no failure {@code failure} happens. */
    record Of(Failure failure) implements Requirement {
        @Override
        public String column() {
            return failure.column();
        }

        @Override
        public boolean failedIn(Set<Failure> failures) {
            return failures.contains(failure);
        }
    }

    /** Any failure first, then each requirement in {@link Failure} order. */
    static List<Requirement> all() {
        List<Requirement> all = new ArrayList<>();
        all.add(new Any());
        for (Failure f : Failure.values()) {
            all.add(new Of(f));
        }
        return all;
    }
}
