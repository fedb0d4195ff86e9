package sitcov.vehicles;

import java.util.ArrayList;
import java.util.List;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;

/**
 * The autonomous car's waypoint register: waypoints are created here (faults 1–4 displace them,
 * fault 0 reuses the previous identity) and looked up by identity, first registered first, so a
 * reused identity finds the stale waypoint.
 */
final class Waypoints {
    private final FaultSwitchboard faults;
    private final List<Waypoint> registered = new ArrayList<>();
    private int nextId = 1;
    private int lastId;

    Waypoints(FaultSwitchboard faults) {
        this.faults = faults;
    }

    /** Registers a waypoint at ({@code x}, {@code y}) and returns the identity to look it up by. */
    int create(double x, double y, Waypoint.Kind kind) {
        double px = x;
        double py = y;
        Fault displacement = displacementFault();
        if (displacement != null) {
            px += switch (displacement) {
                case WAYPOINTS_NORTH_WEST, WAYPOINTS_SOUTH_WEST -> -1;
                default -> 1;
            };
            py += switch (displacement) {
                case WAYPOINTS_NORTH_WEST, WAYPOINTS_NORTH_EAST -> -1;
                default -> 1;
            };
            faults.effective(displacement);
        }
        int id = nextId++;
        if (faults.isActive(Fault.STALE_WAYPOINT_IDENTITY) && lastId != 0) {
            id = lastId;
            if (lookup(id) != null) {
                faults.effective(Fault.STALE_WAYPOINT_IDENTITY);
            } else {
                faults.reached(Fault.STALE_WAYPOINT_IDENTITY);
            }
        }
        lastId = id;
        registered.add(new Waypoint(id, px, py, kind));
        return id;
    }

    /** The first waypoint registered under {@code id}, or null. */
    Waypoint lookup(int id) {
        for (Waypoint w : registered) {
            if (w.id() == id) {
                return w;
            }
        }
        return null;
    }

    /** Forgets every waypoint registered under {@code id}. */
    void remove(int id) {
        registered.removeIf(w -> w.id() == id);
    }

    void clear() {
        registered.clear();
    }

    private Fault displacementFault() {
        // only the lowest-numbered active displacement applies, as in the original
        for (Fault f : new Fault[] {Fault.WAYPOINTS_NORTH_WEST, Fault.WAYPOINTS_NORTH_EAST,
            Fault.WAYPOINTS_SOUTH_WEST, Fault.WAYPOINTS_SOUTH_EAST}) {
            if (faults.isActive(f)) {
                return f;
            }
        }
        return null;
    }
}
