package sitcov.seam;

import java.util.ArrayList;
import java.util.List;
import java.util.random.RandomGenerator;
import sitcov.control.Vehicle;
import sitcov.engine.ReadOnlyView;

/** The radar reports no track at all on a share of ticks, drawn tick by tick from the fault's stream. */
final class RadarDropout extends ObservationView {
    private RandomGenerator draws;
    private double share;
    private boolean dropping;
    private List<Vehicle> none = new ReadOnlyView<>(new ArrayList<>());

    RadarDropout(RandomGenerator draws, double share) {
        this.draws = draws;
        this.share = share;
    }

    @Override
    void started() {
        dropping = draws.nextDouble() < share;
    }

    @Override
    int parts() {
        return Part.TRAFFIC;
    }

    @Override
    public boolean acting() {
        return dropping;
    }

    @Override
    public List<Vehicle> traffic() {
        return dropping ? none : real.traffic();
    }
}
