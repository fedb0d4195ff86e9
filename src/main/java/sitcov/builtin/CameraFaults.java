package sitcov.builtin;

import java.util.List;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.geom.Compass;
import sitcov.sensors.CameraSettings;
import sitcov.sensors.LaneEstimate;
import sitcov.sensors.MarkingCamera;

/** Faults 8–13 degrade the road-marking camera's settings. */
final class CameraFaults {
    static final List<Fault> CAMERA = List.of(Fault.MARKING_ARC_FIRST_HALF_REMOVED, Fault.MARKING_ARC_SECOND_HALF_REMOVED,
            Fault.MARKING_HALF_ANGULAR_RESOLUTION, Fault.MARKING_SCAN_STARTS_HALF_WAY, Fault.MARKING_HALF_RANGE,
            Fault.MARKING_HALF_RANGE_RESOLUTION);

    private CameraFaults() {
    }

    /** The settings of each set of camera faults, indexed by the set's bits in {@link #CAMERA} order. */
    private static final CameraSettings[] BY_SET = new CameraSettings[1 << 6];

    static {
        for (int set = 0; set < BY_SET.length; set++) {
            BY_SET[set] = degraded(set);
        }
    }

    /**
     * The camera settings with every active camera fault applied; STANDARD itself when none is
     * active. Asked each tick: a run forked from the fault-free one switches its fault on mid-run.
     */
    static CameraSettings settings(FaultSwitchboard faults) {
        int set = 0;
        for (int k = 0; k < CAMERA.size(); k++) {
            if (faults.isActive(CAMERA.get(k))) {
                set |= 1 << k;
            }
        }
        return BY_SET[set];
    }

    /** The settings {@code fault} alone leaves the camera. */
    static CameraSettings alone(Fault fault) {
        return BY_SET[1 << CAMERA.indexOf(fault)];
    }

    private static CameraSettings degraded(int set) {
        CameraSettings s = CameraSettings.STANDARD;
        if (set == 0) {
            return s;
        }
        double left = (set & 1) != 0 ? 0 : s.leftArc();
        double right = (set & 2) != 0 ? 0 : s.rightArc();
        double angular = s.angularStep() * ((set & 4) != 0 ? 2 : 1);
        double start = (set & 8) != 0 ? s.range() / 2 : s.rangeStart();
        double range = s.range() / ((set & 16) != 0 ? 2 : 1);
        double step = s.rangeStep() * ((set & 32) != 0 ? 2 : 1);
        return new CameraSettings(left, right, range, angular, step, start);
    }

    /**
     * For a fault-free run watching camera faults from the shadows: looks again with each watched
     * fault's settings, with a camera of its own (so the car's camera keeps the fault-free car's
     * state), and records whether it would have seen the lane otherwise than {@code seen}.
     */
    static void watchFromShadows(FaultSwitchboard faults, MarkingCamera[] cameras, MarkingCamera template,
                                 double x, double y, Compass lane, LaneEstimate seen) {
        for (int k = 0; k < CAMERA.size(); k++) {
            Fault f = CAMERA.get(k);
            if (faults.watches(f) && !faults.isActive(f)) {
                if (cameras[k] == null) {
                    cameras[k] = template.another();
                }
                LaneEstimate degraded = cameras[k].look(x, y, lane, BY_SET[1 << k]);
                if (degraded.equals(seen)) {
                    faults.reached(f);
                } else {
                    faults.effective(f);
                }
            }
        }
    }

    /** Whether every active camera fault is recorded as far as anyone will read: the comparison look can be skipped. */
    static boolean allRecorded(FaultSwitchboard faults) {
        for (Fault f : CAMERA) {
            if (faults.isActive(f) && !faults.recorded(f)) {
                return false;
            }
        }
        return true;
    }

    /** Records a scan with the degraded camera: effective when it saw the lane differently. */
    static void record(FaultSwitchboard faults, boolean differed) {
        for (Fault f : CAMERA) {
            if (faults.isActive(f)) {
                if (differed) {
                    faults.effective(f);
                } else {
                    faults.reached(f);
                }
            }
        }
    }
}
