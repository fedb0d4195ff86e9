package sitcov.export;

import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;

/** What a check over many seeds found wrong: reported together, the first few in full, so one run shows the pattern. */
final class Failures {
    private static final int SHOWN = 12;
    private final List<String> found = new ArrayList<>();

    void add(long seed, String what) {
        found.add("seed " + seed + ": " + what);
    }

    void assertNone(String check) {
        if (!found.isEmpty()) {
            fail(found.size() + " times " + check + " does not hold:\n  "
                    + String.join("\n  ", found.subList(0, Math.min(SHOWN, found.size())))
                    + (found.size() > SHOWN ? "\n  …" : ""));
        }
    }
}
