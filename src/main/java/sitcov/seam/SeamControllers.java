package sitcov.seam;

import java.util.Collection;
import java.util.Set;
import sitcov.control.Controller;
import sitcov.control.ControllerFactory;
import sitcov.control.RunStart;

/**
 * Versions of a reference controller with seam faults: the reference's controllers, each wrapped in
 * a {@link SeamController} that distorts what it observes and what it commands. Works for any
 * controller (in process, or a program: what the protocol writes is the distorted observation); a run
 * can be forked where a fault departs when the reference's controllers can be copied.
 */
public final class SeamControllers {
    private SeamControllers() {
    }

    /** The reference's controllers with {@code fault} switched on. */
    public static ControllerFactory switchedOn(SeamFault fault, ControllerFactory reference) {
        return new Wrapped(reference, Set.of(fault), Set.of());
    }

    /** The reference's controllers, unchanged, watching {@code faults} from the shadows. */
    public static ControllerFactory watching(Collection<SeamFault> faults, ControllerFactory reference) {
        return new Wrapped(reference, Set.of(), Set.copyOf(faults));
    }

    /** The board of a run's controller made here. */
    public static SeamBoard board(Controller controller) {
        if (controller instanceof SeamController c) {
            return c.board();
        }
        throw new IllegalArgumentException("the run's controller has no seam faults");
    }

    private record Wrapped(ControllerFactory reference, Set<SeamFault> on, Set<SeamFault> watched)
            implements ControllerFactory {
        @Override
        public Controller start(RunStart run) {
            SeamBoard board = new SeamBoard();
            Distortion[] distortions = new Distortion[SeamFault.values().length];
            for (SeamFault f : SeamFault.values()) {
                if (on.contains(f) || watched.contains(f)) {
                    distortions[f.ordinal()] = f.distortion(run.streams());
                    if (on.contains(f)) {
                        board.switchOn(f);
                    } else {
                        board.watch(f);
                    }
                }
            }
            return new SeamController(reference.start(run), board, distortions);
        }

        @Override
        public boolean copyable() {
            return reference.copyable();
        }

        @Override
        public ControllerFactory unforked() {
            return new Wrapped(reference.unforked(), on, watched);
        }
    }
}
