package sitcov.seam;

import java.util.ArrayList;
import java.util.List;
import sitcov.control.Vehicle;
import sitcov.engine.ReadOnlyView;

/** The radar reports only the tracks whose front lies within a shorter range of the car's front. */
final class TrafficWithin extends ObservationView {
    private double range;
    private List<Vehicle> kept = new ArrayList<>();
    private List<Vehicle> view = new ReadOnlyView<>(kept);
    private long keptAt = -1;

    TrafficWithin(double range) {
        this.range = range;
    }

    @Override
    int parts() {
        return Part.TRAFFIC;
    }

    @Override
    public List<Vehicle> traffic() {
        if (keptAt != tick) {
            kept.clear();
            List<Vehicle> all = real.traffic();
            double x = real.x();
            double y = real.y();
            for (int i = 0, n = all.size(); i < n; i++) {
                Vehicle v = all.get(i);
                if (Math.hypot(v.x() - x, v.y() - y) <= range) {
                    kept.add(v);
                }
            }
            keptAt = tick;
        }
        return view;
    }
}
