package sitcov.seam;

import java.util.ArrayList;
import java.util.List;
import sitcov.engine.ReadOnlyView;
import sitcov.geom.Box;

/** The LIDAR's obstacle list holds only the parked cars whose centre lies within a shorter range of the car's front. */
final class ObstaclesWithin extends ObservationView {
    private double range;
    private List<Box> kept = new ArrayList<>();
    private List<Box> view = new ReadOnlyView<>(kept);
    private long keptAt = -1;

    ObstaclesWithin(double range) {
        this.range = range;
    }

    @Override
    int parts() {
        return Part.OBSTACLES;
    }

    @Override
    public List<Box> obstacles() {
        if (keptAt != tick) {
            kept.clear();
            List<Box> all = real.obstacles();
            double x = real.x();
            double y = real.y();
            for (int i = 0, n = all.size(); i < n; i++) {
                Box b = all.get(i);
                if (Math.hypot(b.centreX() - x, b.centreY() - y) <= range) {
                    kept.add(b);
                }
            }
            keptAt = tick;
        }
        return view;
    }
}
