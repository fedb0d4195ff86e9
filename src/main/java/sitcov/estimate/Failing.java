package sitcov.estimate;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import sitcov.judge.Requirement;
import sitcov.oracle.Failure;

/** What an estimate counts as a failing run: any failure at all, or a violation of one of the controller's requirements. */
public sealed interface Failing {
    /** Its name in files: {@code any}, or the requirement's key. */
    String column();

    boolean in(Set<Failure> failures);

    /** Any failure of the run. */
    record Any() implements Failing {
        @Override
        public String column() {
            return "any";
        }

        @Override
        public boolean in(Set<Failure> failures) {
            return !failures.isEmpty();
        }
    }

    /** A violation of {@code requirement}. */
    record Of(Requirement requirement) implements Failing {
        @Override
        public String column() {
            return requirement.key();
        }

        @Override
        public boolean in(Set<Failure> failures) {
            return requirement.violatedBy(failures);
        }
    }

    /** Any failure first, then each requirement in {@link Requirement}'s order. */
    static List<Failing> all() {
        List<Failing> all = new ArrayList<>();
        all.add(new Any());
        for (Requirement r : Requirement.values()) {
            all.add(new Of(r));
        }
        return all;
    }
}
