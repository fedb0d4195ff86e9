package sitcov.render;

import java.util.ArrayList;
import java.util.List;
import sitcov.geom.Box;
import sitcov.judge.RunObserver;
import sitcov.oracle.AccidentDetector;
import sitcov.vehicles.Telemetry;
import sitcov.control.Vehicle;

/** Every vehicle's footprint every {@code every} ticks (and at the last tick), for an animation. */
public final class FrameRecorder implements RunObserver {
    /** One moment: the tick, the autonomous car's footprint, the moving cars', and the accidents so far. */
    public record Frame(long tick, Box car, List<Box> traffic, int accidents) {
    }

    private final int every;
    private final List<Frame> frames = new ArrayList<>();
    private Frame last;

    public FrameRecorder(int every) {
        if (every < 1) {
            throw new IllegalArgumentException("a frame every " + every + " ticks");
        }
        this.every = every;
    }

    @Override
    public void afterTick(long tick, Telemetry run, AccidentDetector detector) {
        List<Box> traffic = new ArrayList<>();
        Box car = run.car().footprint();
        for (Vehicle v : run.movingCars()) {
            if (v.isActive()) {
                traffic.add(v.footprint());
            }
        }
        last = new Frame(tick, car, List.copyOf(traffic), detector.accidents().size());
        if (tick % every == 0) {
            frames.add(last);
        }
    }

    /** The frames, ending with the run's last tick. */
    public List<Frame> frames() {
        List<Frame> all = new ArrayList<>(frames);
        if (last != null && (all.isEmpty() || all.get(all.size() - 1) != last)) {
            all.add(last);
        }
        return all;
    }

}
