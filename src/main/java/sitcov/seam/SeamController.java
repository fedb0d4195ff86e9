package sitcov.seam;

import sitcov.control.Command;
import sitcov.control.Controller;
import sitcov.control.Observation;
import sitcov.control.RunEnd;

/**
 * The reference controller with seam faults between it and the world: each tick it hands the
 * controller the observation as the fault switched on distorts it, and hands the world the command
 * as it distorts it; every fault on or watched is judged on what the controller read and asked for.
 * The controller cannot tell, except through what it observes.
 */
final class SeamController implements Controller {
    private Controller reference;
    private SeamBoard board;
    /** Each fault's distortion by its ordinal; null for a fault neither on nor watched. */
    private Distortion[] distortions;
    private Consults consults = new Consults();
    private Motion asked = new Motion();
    private Motion given = new Motion();

    SeamController(Controller reference, SeamBoard board, Distortion[] distortions) {
        this.reference = reference;
        this.board = board;
        this.distortions = distortions;
    }

    SeamBoard board() {
        return board;
    }

    @Override
    public void step(Observation real, Command out) {
        long tick = real.tick();
        Observation shown = real;
        for (int i = 0; i < distortions.length; i++) {
            Distortion d = distortions[i];
            if (d != null && board.watches(i)) {
                d.startTick(real, tick);
                if (board.isActive(i) && d instanceof ObservationView view) {
                    shown = view;
                }
            }
        }
        consults.start(shown);
        reference.step(consults, out);
        boolean commandsSeen = false;
        for (int i = 0; i < distortions.length; i++) {
            if (distortions[i] instanceof ObservationView view && board.watches(i)) {
                boolean read = (consults.mask() & view.parts()) != 0;
                board.saw(i, tick, read && view.acting(), read && Sameness.differs(view, real, view.parts(), consults));
                view.endTick(consults);
            } else if (distortions[i] instanceof CommandDistortion command && board.watches(i)) {
                if (!commandsSeen) {
                    asked.of(out);
                    commandsSeen = true;
                }
                command.distort(asked, real, given);
                board.saw(i, tick, command.acting(), asked.appliesOtherwise(given, real.speed()));
                if (board.isActive(i)) {
                    given.into(out);
                    command.handed(given);
                } else {
                    command.handed(asked);
                }
            }
        }
    }

    @Override
    public java.util.Set<sitcov.control.Sensor> sensors() {
        return reference.sensors();
    }

    @Override
    public void end(RunEnd how) {
        reference.end(how);
    }
}
