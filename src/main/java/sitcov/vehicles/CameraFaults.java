package sitcov.vehicles;

import java.util.List;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;

/** Faults 8–13 degrade the road-marking camera's settings. */
final class CameraFaults {
    static final List<Fault> CAMERA = List.of(Fault.MARKING_ARC_FIRST_HALF_REMOVED, Fault.MARKING_ARC_SECOND_HALF_REMOVED,
            Fault.MARKING_HALF_ANGULAR_RESOLUTION, Fault.MARKING_SCAN_STARTS_HALF_WAY, Fault.MARKING_HALF_RANGE,
            Fault.MARKING_HALF_RANGE_RESOLUTION);

    private CameraFaults() {
    }

    /** The camera settings with every active camera fault applied; STANDARD itself when none is active. */
    static CameraSettings settings(FaultSwitchboard faults) {
        CameraSettings s = CameraSettings.STANDARD;
        if (CAMERA.stream().noneMatch(faults::isActive)) {
            return s;
        }
        double left = faults.isActive(Fault.MARKING_ARC_FIRST_HALF_REMOVED) ? 0 : s.leftArc();
        double right = faults.isActive(Fault.MARKING_ARC_SECOND_HALF_REMOVED) ? 0 : s.rightArc();
        double angular = s.angularStep() * (faults.isActive(Fault.MARKING_HALF_ANGULAR_RESOLUTION) ? 2 : 1);
        double start = faults.isActive(Fault.MARKING_SCAN_STARTS_HALF_WAY) ? s.range() / 2 : s.rangeStart();
        double range = s.range() / (faults.isActive(Fault.MARKING_HALF_RANGE) ? 2 : 1);
        double step = s.rangeStep() * (faults.isActive(Fault.MARKING_HALF_RANGE_RESOLUTION) ? 2 : 1);
        return new CameraSettings(left, right, range, angular, step, start);
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
