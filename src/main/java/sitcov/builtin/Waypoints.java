package sitcov.builtin;

import java.util.ArrayList;
import java.util.List;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;

/**
 * The autonomous car's waypoint register: waypoints are created here (faults 1–4 displace them,
 * fault 0 reuses the previous identity) and looked up by identity, oldest first. The register
 * remembers the waypoint reached last (as the original left reached waypoints in the world), so a
 * reused identity finds that stale waypoint; with fresh identities it is never looked up.
 */
final class Waypoints {
    private static final Fault[] DISPLACEMENTS = {Fault.WAYPOINTS_NORTH_WEST, Fault.WAYPOINTS_NORTH_EAST,
        Fault.WAYPOINTS_SOUTH_WEST, Fault.WAYPOINTS_SOUTH_EAST};

    private FaultSwitchboard faults;
    private List<Waypoint> registered = new ArrayList<>();
    private Waypoint lastReached;
    private int nextId = 1;
    private int lastId;

    Waypoints(FaultSwitchboard faults) {
        this.faults = faults;
    }

    /** Registers a waypoint at ({@code x}, {@code y}) and returns the identity to look it up by. */
    int create(double x, double y, Waypoint.Kind kind) {
        double px = x;
        double py = y;
        // displacements add up when several are on, so each fault of a set acts
        for (Fault f : DISPLACEMENTS) {
            if (faults.watches(f)) {
                if (faults.isActive(f)) {
                    px += f == Fault.WAYPOINTS_NORTH_WEST || f == Fault.WAYPOINTS_SOUTH_WEST ? -1 : 1;
                    py += f == Fault.WAYPOINTS_NORTH_WEST || f == Fault.WAYPOINTS_NORTH_EAST ? -1 : 1;
                }
                faults.effective(f);
            }
        }
        int id = nextId++;
        if (faults.watches(Fault.STALE_WAYPOINT_IDENTITY) && lastId != 0) {
            faults.reached(Fault.STALE_WAYPOINT_IDENTITY);
            // the reused identity is state the fault-free car does not have, effective or not
            faults.departs(Fault.STALE_WAYPOINT_IDENTITY);
            if (faults.isActive(Fault.STALE_WAYPOINT_IDENTITY)) {
                id = lastId;
            }
        }
        lastId = id;
        registered.add(new Waypoint(id, px, py, kind));
        return id;
    }

    /** The oldest waypoint remembered under {@code id}, or null. */
    Waypoint lookup(int id) {
        for (Waypoint w : registered) {
            if (w.id() == id) {
                if (lastReached != null && lastReached.id() == id) {
                    // only a reused identity gets here: the stale waypoint shadows the new one
                    faults.effective(Fault.STALE_WAYPOINT_IDENTITY);
                    return lastReached;
                }
                return w;
            }
        }
        return null;
    }

    /** Retires every waypoint registered under {@code id}; the last of them is remembered as reached. */
    void remove(int id) {
        for (int i = registered.size() - 1; i >= 0; i--) {
            if (registered.get(i).id() == id) {
                lastReached = registered.remove(i);
            }
        }
    }

    void clear() {
        registered.clear();
        lastReached = null;
    }
}
