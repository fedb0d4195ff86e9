package sitcov.export;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import sitcov.oracle.Accident;
import sitcov.oracle.ExcusedContact;

/**
 * One thing a recorded run's file declares happened, as an event a player reports when it sees it: an accident of
 * the run ({@code accident<n>}, numbered as the run's accidents), a contact of the car under test the blame rules
 * excused ({@code excused<n>}), or a contact between two other vehicles, which the oracle does not judge
 * ({@code contact<n>}). A contact names both vehicles, so a player that detects collisions reports it when it sees
 * them touch; an accident with no other party is marked at its time.
 *
 * @param id      the event's variable, and the start of its name
 * @param tick    the tick at whose end it began (sample {@code tick + 1})
 * @param what    the accident's type, the blame rule that excused the contact, or {@code NOT_JUDGED}
 * @param other   the second vehicle of a contact; empty for an accident with no other party
 * @param found   whether it is the accident that found the run's fault
 */
record Declared(String id, long tick, String what, String entity, Optional<String> other, String where, boolean found) {
    static final String NOT_JUDGED = "NOT_JUDGED";

    /** Everything the run's recording declares, in the order it began (accidents first within a tick). */
    static List<Declared> of(RunRecording run, Optional<Accident> found) {
        List<Declared> out = new ArrayList<>();
        int n = 1;
        for (Accident a : run.accidents()) {
            String other = OpenScenario.otherParty(run, a);
            out.add(new Declared("accident" + n++, a.tick(), a.type().name(), RunRecording.EGO,
                    other.equals("none") ? Optional.empty() : Optional.of(other), at(a.x(), a.y()),
                    found.isPresent() && found.get().equals(a)));
        }
        n = 1;
        for (ExcusedContact c : run.excused()) {
            out.add(new Declared("excused" + n++, c.tick(), c.blame().name(), RunRecording.EGO,
                    Optional.of(OpenScenario.vehicleNamed(run, c.otherParty())), at(c.x(), c.y()), false));
        }
        n = 1;
        for (RunRecording.Touch t : run.traffic()) {
            out.add(new Declared("contact" + n++, t.tick(), NOT_JUDGED, t.entity(), Optional.of(t.other()), "", false));
        }
        out.sort(Comparator.comparingLong(Declared::tick));
        return out;
    }

    private static String at(double x, double y) {
        return " at x=" + Xml.fixed(AsamFrame.x(x), 2) + " y=" + Xml.fixed(AsamFrame.y(y), 2);
    }

    /** Whether a player can see it as two vehicles touching. */
    boolean isContact() {
        return other.isPresent();
    }

    /** The event's name: what, who, when and where, in words. */
    String describe() {
        String kind = id.startsWith("accident") ? what
                : what.equals(NOT_JUDGED) ? "contact the oracle does not judge" : "contact excused (" + what + ")";
        return id + ": " + kind + ", " + entity + other.map(o -> " with " + o).orElse("") + ", at tick " + tick + " ("
                + Xml.fixed(AsamFrame.seconds(tick), 1) + " s)" + where + (found ? "; it found the fault" : "");
    }
}
