package sitcov.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.geom.Ellipse2D;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import sitcov.faults.Activation;
import sitcov.geom.Box;
import sitcov.oracle.Accident;
import sitcov.oracle.RunResult;
import sitcov.world.WorldMap;

/**
 * A replay as an animated GIF: the fault-free run and its faulty twin side by side (or one run), at
 * a small scale. Each frame draws every vehicle, the path driven so far, each accident from its
 * tick on and a ring where the fault first acted, from then on; above each side the tick and what
 * has happened, and once its run has ended, how it ended. A side whose run has ended holds its
 * last frame. Where no car moves for a while the animation skips ahead, and says so, rather than
 * show a car standing still for minutes. {@link GifFrames} keeps the file small.
 */
public final class ReplayAnimation {
    /** One run to animate: its frames, its path, how it went, and, on a faulty side, the fault's marks. */
    public record Side(String label, TrajectoryRecorder path, List<FrameRecorder.Frame> frames, RunResult result,
                       Optional<Activation> activation, Optional<Accident> newAccident) {
        public Side {
            frames = List.copyOf(frames);
            if (frames.isEmpty()) {
                throw new IllegalArgumentException("a side to animate needs frames");
            }
        }

        long end() {
            return frames.get(frames.size() - 1).tick();
        }
    }

    /** A frame of the animation: its tick, and the tick of the frame before if still ticks were skipped between (else -1). */
    record Shot(long tick, long skippedFrom) {
        boolean afterSkip() {
            return skippedFrom >= 0;
        }
    }

    /** Pixels per metre: two maps side by side fit a laptop screen. */
    static final int SCALE = 3;
    /** Hundredths of a second a frame is shown: a frame a simulated second plays 12.5 times as fast. */
    static final int DELAY = 8;
    /** A frame after a skip stays longer, so the jump is seen; the last frame longer still before the loop. */
    static final int SKIP_DELAY = 120;
    static final int LAST_DELAY = 300;
    /**
     * Frames of standing still shown before the rest of a still stretch is skipped: ten simulated
     * seconds, so a wait at a junction plays whole.
     */
    static final int HOLD = 10;
    static final int MAX_FRAMES = 200;
    static final int HEADER = 36;
    static final int GAP = 8;
    /** How far a car must move between frames (metres, or degrees of heading) to count as moving. */
    private static final double STILL = 0.02;

    private ReplayAnimation() {
    }

    /** Writes the GIF of {@code sides} (one or two) to {@code file}, whole or not at all. */
    public static void write(WorldMap map, List<Side> sides, Path file) throws IOException {
        if (sides.isEmpty() || sides.size() > 2) {
            throw new IllegalArgumentException("an animation shows one or two runs, not " + sides.size());
        }
        BufferedImage base = new MapRenderer(SCALE).renderWithoutTraffic(map);
        List<Shot> shots = shots(sides);
        int width = sides.size() * base.getWidth() + (sides.size() - 1) * GAP;
        try (GifFrames gif = GifFrames.open(file, width, HEADER + base.getHeight(), must())) {
            for (int i = 0; i < shots.size(); i++) {
                BufferedImage frame = frame(map, base, sides, shots.get(i));
                boolean last = i == shots.size() - 1;
                boolean skipNext = !last && shots.get(i + 1).afterSkip();
                gif.add(frame, last ? LAST_DELAY : shots.get(i).afterSkip() || skipNext ? SKIP_DELAY : DELAY);
            }
            gif.commit();
        }
    }

    /** Colours every frame must show exactly: the cars', the paths', the markers'. */
    private static List<Color> must() {
        List<Color> colours = new ArrayList<>(List.of(MapStyle.MOVING_CAR, MapStyle.AUTONOMOUS_CAR, Color.BLACK,
                Color.WHITE, MapStyle.TEXT, MapStyle.CAPTION, RunMarks.DRIVING, RunMarks.CROSSING, RunMarks.OVERTAKING,
                ReplayPicture.EFFECT, ReplayPicture.NEW_ACCIDENT));
        for (var type : sitcov.oracle.AccidentType.values()) {
            colours.add(RunMarks.markerColour(type));
        }
        return colours;
    }

    /**
     * The ticks to draw: every recorded frame of any side, except that once no car has moved (and
     * nothing happened) for {@link #HOLD} frames, the rest of that still stretch is skipped; at most
     * {@link #MAX_FRAMES}, thinned evenly if more, always ending on the last tick.
     */
    static List<Shot> shots(List<Side> sides) {
        java.util.TreeSet<Long> ticks = new java.util.TreeSet<>();
        for (Side s : sides) {
            s.frames().forEach(f -> ticks.add(f.tick()));
        }
        List<Long> all = new ArrayList<>(ticks);
        List<Shot> shots = new ArrayList<>();
        shots.add(new Shot(all.get(0), -1));
        int still = 0;
        long shown = all.get(0);
        long skippedFrom = -1;
        for (int i = 1; i < all.size(); i++) {
            long a = shown;
            long b = all.get(i);
            // against the last frame shown, so a car creeping along is not skipped a bit at a time
            boolean changed = sides.stream().anyMatch(s -> changed(s, a, b));
            boolean lastTick = i == all.size() - 1;
            if (changed || lastTick || still < HOLD) {
                still = changed ? 0 : still + 1;
                shots.add(new Shot(b, skippedFrom));
                shown = b;
                skippedFrom = -1;
            } else if (skippedFrom < 0) {
                skippedFrom = a;
            }
        }
        if (shots.size() <= MAX_FRAMES) {
            return shots;
        }
        List<Shot> fewer = new ArrayList<>();
        for (int k = 0; k < MAX_FRAMES; k++) { // evenly spaced, the first and the last among them
            fewer.add(shots.get((int) Math.round((double) k * (shots.size() - 1) / (MAX_FRAMES - 1))));
        }
        return fewer;
    }

    /** Whether side {@code s} shows something new at tick {@code b} that it did not at {@code a}. */
    private static boolean changed(Side s, long a, long b) {
        if (a >= s.end()) {
            return false;
        }
        if (b >= s.end()) {
            return true; // its outcome appears
        }
        Box was = at(s, a).car();
        Box now = at(s, b).car();
        if (was == null || now == null) {
            return was != now;
        }
        if (Math.hypot(now.centreX() - was.centreX(), now.centreY() - was.centreY()) > STILL
                || Math.abs(now.bearing() - was.bearing()) > STILL) {
            return true;
        }
        boolean accident = s.result().accidents().stream().anyMatch(x -> x.tick() > a && x.tick() <= b);
        long acts = s.activation().filter(Activation::effective).map(Activation::firstEffectiveTick).orElse(-1L);
        return accident || acts > a && acts <= b;
    }

    /** The side's frame at tick {@code t}: the last recorded at or before it (its last, once it has ended). */
    private static FrameRecorder.Frame at(Side s, long t) {
        List<FrameRecorder.Frame> frames = s.frames();
        int lo = 0;
        int hi = frames.size() - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (frames.get(mid).tick() <= t) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return frames.get(lo);
    }

    private static BufferedImage frame(WorldMap map, BufferedImage base, List<Side> sides, Shot shot) {
        int w = sides.size() * base.getWidth() + (sides.size() - 1) * GAP;
        BufferedImage frame = new BufferedImage(w, HEADER + base.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = frame.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(MapStyle.CAPTION);
            g.fillRect(0, 0, frame.getWidth(), frame.getHeight());
            for (int i = 0; i < sides.size(); i++) {
                side(g, map, base, sides.get(i), shot, sides.size(), i * (base.getWidth() + GAP));
            }
        } finally {
            g.dispose();
        }
        return frame;
    }

    private static void side(Graphics2D g, WorldMap map, BufferedImage base, Side s, Shot shot, int count, int x) {
        FrameRecorder.Frame f = at(s, shot.tick());
        g.drawImage(base, x, HEADER, null);
        header(g, s, f, shot, count, x, base.getWidth());
        int worldHeight = MapRenderer.worldHeightPixels(SCALE);
        AffineTransform saved = g.getTransform();
        g.setClip(x, HEADER, base.getWidth(), worldHeight); // nothing spills onto the caption or the other side
        g.translate(x, HEADER);
        g.scale(SCALE, SCALE);
        new RunMarks(g, new MapStyle(SCALE)).path(map, s.path(), 2, entriesUpTo(s.path(), f.tick()));
        for (Box b : f.traffic()) {
            fill(g, b, MapStyle.MOVING_CAR, MapStyle.MOVING_OUTLINE);
        }
        if (f.car() != null) {
            fill(g, f.car(), MapStyle.AUTONOMOUS_CAR, MapStyle.AUTONOMOUS_OUTLINE);
            // at three pixels a metre the 2 m car is a speck: a ring finds it at a glance
            g.setColor(MapStyle.AUTONOMOUS_CAR);
            g.setStroke(new BasicStroke(0.8f));
            g.draw(new Ellipse2D.Double(f.car().centreX() - 4, f.car().centreY() - 4, 8, 8));
        }
        g.setTransform(saved);
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        RunMarks marks = new RunMarks(g, new MapStyle(SCALE));
        List<Accident> accidents = s.result().accidents().stream().filter(a -> a.tick() <= f.tick()).toList();
        for (int i = accidents.size() - 1; i >= 0; i--) { // the first on top
            Accident a = accidents.get(i);
            marks.marker(a.type(), x + a.x() * SCALE, HEADER + a.y() * SCALE, 5);
        }
        s.newAccident().filter(a -> a.tick() <= f.tick())
                .ifPresent(a -> ring(g, x + a.x() * SCALE, HEADER + a.y() * SCALE, ReplayPicture.NEW_ACCIDENT));
        s.activation().filter(Activation::effective).filter(a -> a.firstEffectiveTick() <= f.tick()).ifPresent(a -> {
            int i = entriesUpTo(s.path(), a.firstEffectiveTick()) - 1;
            if (i >= 0) {
                ring(g, x + s.path().x(i) * SCALE, HEADER + s.path().y(i) * SCALE, ReplayPicture.EFFECT);
            }
        });
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_OFF);
        g.setClip(null);
    }

    /**
     * Two lines over a side: its name and the tick (and any skip), then what has happened so far
     * or, once the run has ended, how it ended.
     */
    private static void header(Graphics2D g, Side s, FrameRecorder.Frame f, Shot shot, int count, int x, int width) {
        g.setColor(MapStyle.TEXT);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
        String skip = !shot.afterSkip() ? "" : " (skipped from t=" + shot.skippedFrom()
                + (count == 1 ? ": the car stood still)" : ": neither car moved)");
        g.drawString(s.label() + " · t=" + shot.tick() + skip, x + 6, 15);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        String status;
        if (shot.tick() >= s.end()) {
            status = OutcomeText.of(s.result().outcome(), s.result().ticks(), s.result().accidents());
            g.setColor(s.result().accidents().isEmpty() ? MapStyle.TEXT : ReplayPicture.NEW_ACCIDENT);
        } else {
            List<String> events = new ArrayList<>();
            s.activation().filter(Activation::effective).filter(a -> a.firstEffectiveTick() <= f.tick())
                    .ifPresent(a -> events.add("fault " + a.fault().id() + " first acts at t=" + a.firstEffectiveTick()
                            + " (orange ring)"));
            s.result().accidents().stream().filter(a -> a.tick() <= f.tick())
                    .forEach(a -> events.add(a.type() + " at t=" + a.tick()));
            status = events.isEmpty() ? "driving; nothing has happened yet" : String.join(" · ", events);
        }
        FontMetrics fm = g.getFontMetrics();
        while (fm.stringWidth(status) > width - 12 && status.length() > 2) {
            status = status.substring(0, status.length() - 2) + "…";
        }
        g.drawString(status, x + 6, 31);
    }

    /** How many of the path's entries are at or before tick {@code t}. */
    private static int entriesUpTo(TrajectoryRecorder path, long t) {
        int lo = 0;
        int hi = path.ticks();
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (path.tick(mid) <= t) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    private static void ring(Graphics2D g, double x, double y, Color colour) {
        g.setColor(colour);
        g.setStroke(new BasicStroke(2.5f));
        g.draw(new Ellipse2D.Double(x - 9, y - 9, 18, 18));
    }

    private static void fill(Graphics2D g, Box b, Color fill, Color outline) {
        var shape = MapShapes.polygon(b);
        g.setColor(fill);
        g.fill(shape);
        g.setColor(outline);
        g.setStroke(new BasicStroke(0.3f));
        g.draw(shape);
    }

    static int[] pixels(BufferedImage image) {
        return ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
    }
}
