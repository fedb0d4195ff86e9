package sitcov.export;

import java.util.List;
import sitcov.control.Vehicle;
import sitcov.geom.Box;

/**
 * The contacts between vehicles other than the car under test, found tick by tick as the oracle finds the car's:
 * footprints that overlap now and did not a tick before, between two moving cars on the map or a moving car and a
 * parked one. The oracle judges only the car under test, so these are no accidents; a player that reports every
 * contact reports them too, and the export declares them so that its reports can be matched.
 */
final class TrafficContacts {
    private final boolean[][] touchingMoving;
    private final boolean[][] touchingParked;

    TrafficContacts(int moving, int parked) {
        touchingMoving = new boolean[moving][moving];
        touchingParked = new boolean[moving][parked];
    }

    /** Adds to {@code out} the contacts that began at the end of {@code tick}. */
    void step(long tick, List<? extends Vehicle> moving, List<Box> parked, List<RunRecording.Touch> out) {
        for (int i = 0; i < moving.size(); i++) {
            Vehicle a = moving.get(i);
            Box body = a.isActive() ? a.footprint() : null;
            for (int j = i + 1; j < moving.size(); j++) {
                Vehicle b = moving.get(j);
                boolean touching = body != null && b.isActive() && body.overlaps(b.footprint());
                if (touching && !touchingMoving[i][j]) {
                    out.add(new RunRecording.Touch(tick, RunRecording.movingName(i), RunRecording.movingName(j)));
                }
                touchingMoving[i][j] = touching;
            }
            for (int p = 0; p < parked.size(); p++) {
                boolean touching = body != null && body.overlaps(parked.get(p));
                if (touching && !touchingParked[i][p]) {
                    out.add(new RunRecording.Touch(tick, RunRecording.movingName(i), RunRecording.parkedName(p)));
                }
                touchingParked[i][p] = touching;
            }
        }
    }
}
