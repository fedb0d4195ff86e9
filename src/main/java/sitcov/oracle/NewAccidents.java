package sitcov.oracle;

import java.util.ArrayList;
import java.util.List;

/**
 * The accident events of one run that a baseline run of the same map and internal seed does not
 * have: the heart of the differential oracle. Two events are the same accident when they have the
 * same type (and the same parked car) and happened within {@link #SAME_PLACE} metres of each other, at any
 * tick (a fault that only delays the car shifts its accidents in time, it does not cause them).
 * A TIMEOUT matches a TIMEOUT wherever the car was. Each baseline event matches at most one event.
 */
public final class NewAccidents {
    /** How far apart two events may be and still be the same accident. */
    public static final double SAME_PLACE = 10;

    private NewAccidents() {
    }

    public static List<Accident> between(RunResult baseline, RunResult run) {
        List<Accident> unmatched = new ArrayList<>(baseline.accidents());
        List<Accident> fresh = new ArrayList<>();
        for (Accident a : run.accidents()) {
            Accident match = firstSame(unmatched, a);
            if (match == null) {
                fresh.add(a);
            } else {
                unmatched.remove(match);
            }
        }
        return fresh;
    }

    /** The first of {@code baseline} that is the same accident as {@code a}, or null. */
    public static Accident firstSame(List<Accident> baseline, Accident a) {
        for (Accident b : baseline) {
            if (same(a, b)) {
                return b;
            }
        }
        return null;
    }

    private static boolean same(Accident a, Accident b) {
        if (a.type() != b.type()) {
            return false;
        }
        // parked cars keep their ids in every run; moving cars that respawn get theirs in order of
        // leaving, which a fault can change, so for them only the place tells
        if (a.type() == AccidentType.CLASHWITHOBSTACLE && a.otherParty() != b.otherParty()) {
            return false;
        }
        return a.type() == AccidentType.TIMEOUT || Math.hypot(a.x() - b.x(), a.y() - b.y()) <= SAME_PLACE;
    }
}
