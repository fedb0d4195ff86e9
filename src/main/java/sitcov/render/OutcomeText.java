package sitcov.render;

import java.util.List;
import java.util.stream.Collectors;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;

/**
 * How a run ended, in one line for a person watching it (the viewer's header, an animation's
 * last frames): "Reached the Target at t=222", "TIMEOUT at t=4999 …", then its accidents.
 * Ticks are the simulation's (the first is t=0), as every picture writes them.
 */
public final class OutcomeText {
    private static final int LISTED = 2;

    private OutcomeText() {
    }

    /** {@code ticks} is how many ticks the run took, so its last was {@code ticks - 1}. */
    public static String of(Outcome outcome, long ticks, List<Accident> accidents) {
        long last = ticks - 1;
        String end = switch (outcome) {
            case TARGET_REACHED -> "Reached the Target at t=" + last;
            case TIMEOUT -> "TIMEOUT at t=" + last + ", the Target not reached";
            case STOPPED_AT_VERDICT -> "Stopped at t=" + last + ", its verdict settled";
            case CONTROLLER_TIMEOUT -> "CONTROLLER_TIMEOUT at t=" + last + ": the controller gave no command in time";
            case CONTROLLER_ERROR -> "CONTROLLER_ERROR at t=" + last + ": the controller failed (see its log)";
        };
        List<Accident> real = accidents.stream().filter(a -> a.type() != AccidentType.TIMEOUT).toList();
        if (real.isEmpty()) {
            return end;
        }
        String listed = real.stream().limit(LISTED).map(a -> a.type() + " at t=" + a.tick())
                .collect(Collectors.joining(", "));
        return end + " · " + (real.size() == 1 ? "accident: " : real.size() + " accidents: ") + listed
                + (real.size() > LISTED ? " +" + (real.size() - LISTED) + " more" : "");
    }
}
