package sitcov.viewer;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;
import java.awt.geom.AffineTransform;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.RoundRectangle2D;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import sitcov.control.Observation;
import sitcov.control.SelfReport;
import sitcov.control.Sensor;
import sitcov.control.Vehicle;
import sitcov.geom.Bearing;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.world.Dimensions;
import sitcov.judge.LiveRun;
import sitcov.judge.RunHistory;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.oracle.NearMiss;
import sitcov.oracle.NearMisses;
import sitcov.render.MapRenderer;
import sitcov.render.MapShapes;
import sitcov.render.NearMissText;
import sitcov.render.OutcomeText;

/**
 * Paints one live run as it stands: the map (drawn once), every vehicle, what the car's controller
 * observed this tick, each accident where it happened, and a header with the car's state and how close
 * the run has come to each accident so far (its near misses). What it observed is the observation the
 * seam hands any controller, as far as the controller took it ({@link sitcov.control.Sensor}): the radar
 * tracks (an orange dot at each tracked vehicle's front, a line to where it will be in a second), the
 * LIDAR's obstacles (parked cars outlined in orange), the camera's 90° fan to 10 m with the samples where
 * its rays met markings, the LIDAR's half disc to 25 m with the rays of its sweep that hit something. A
 * run replayed from its recorded commands is the recorded run, so its observation is the one its
 * controller was handed (before any seam fault changed it). It only reads the run: the model never
 * knows it is watched.
 */
public final class RunPainter {
    static final int HEADER = 74;
    static final Color CAR = new Color(0x00E5FF);
    static final Color MOVING = new Color(0xB84FD0);
    static final Color ACCIDENT = new Color(0xD7263D);
    private static final Color REACHED = new Color(0x1B6E20);
    private static final Color CAMERA = new Color(255, 230, 80, 70);
    private static final Color LIDAR = new Color(255, 255, 255, 150);
    static final Color CAMERA_HIT = new Color(0xFFD400);
    /** The radar's tracks and the LIDAR's obstacles: what the controller was told of other cars. */
    static final Color SENSED = new Color(0xFF6D00);
    private static final double CAMERA_RANGE = 10;
    private static final double LIDAR_RANGE = 25;

    private final RunHistory history;
    private final String title;
    private final int scale;
    private final BufferedImage base;

    public RunPainter(LiveRun run, String title, int pixelsPerMetre) {
        this.history = new RunHistory(run);
        this.title = title;
        this.scale = pixelsPerMetre;
        this.base = new MapRenderer(pixelsPerMetre).renderWithoutTraffic(run.map());
    }

    /** The run as it stands now. */
    public LiveRun run() {
        return history.current();
    }

    /** The run, stepped on and back. */
    public RunHistory history() {
        return history;
    }

    public int pixelsPerMetre() {
        return scale;
    }

    public Dimension size() {
        return new Dimension(base.getWidth(), HEADER + base.getHeight());
    }

    /** The size of a pane at {@code pixelsPerMetre}: the header over the map and its caption. */
    static Dimension paneSize(int pixelsPerMetre) {
        Dimension map = MapRenderer.imageSize(pixelsPerMetre);
        return new Dimension(map.width, HEADER + map.height);
    }

    public void paint(Graphics2D g) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(new Color(0xF3F1EC));
        g.fillRect(0, 0, base.getWidth(), HEADER);
        header(g);
        g.drawImage(base, 0, HEADER, null);
        Shape clip = g.getClip();
        // the scene stays on the map: the LIDAR's reach or a car off the edge never covers the caption
        g.clipRect(0, HEADER, base.getWidth(), MapRenderer.worldHeightPixels(scale));
        AffineTransform saved = g.getTransform();
        g.translate(0, HEADER);
        g.scale(scale, scale);
        Vehicle car = run().telemetry().car();
        Set<Sensor> taken = run().telemetry().sensors();
        Observation sees = run().telemetry().observation();
        sensors(g, car, sees, taken);
        for (Vehicle v : run().telemetry().movingCars()) {
            if (v.isActive()) {
                body(g, v, MOVING);
            }
        }
        body(g, car, CAR);
        if (run().tick() >= 0) { // before its first tick the car has observed nothing
            reported(g, sees, taken);
        }
        g.setTransform(saved);
        accidents(g, run().detector().accidents());
        g.setClip(clip);
    }

    private void header(Graphics2D g) {
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 14));
        g.drawString(title, 8, 18);
        int after = 8 + g.getFontMetrics().stringWidth(title) + 12;
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.setColor(SENSED.darker());
        String observed = observed();
        if (after + g.getFontMetrics().stringWidth(observed) <= base.getWidth() - 8) {
            g.drawString(observed, after, 18);
        }
        boolean ended = run().detector().outcome() != null;
        List<Accident> accidents = run().detector().accidents();
        g.setColor(!ended ? Color.BLACK : accidents.isEmpty() ? REACHED : ACCIDENT);
        fitted(g, status(), ended ? Font.BOLD : Font.PLAIN, 36);
        g.setColor(accidents.isEmpty() ? Color.DARK_GRAY : ACCIDENT);
        fitted(g, accidents.isEmpty() ? "no accident" : accidents.size() + " accident" + (accidents.size() == 1 ? "" : "s")
                + ", the last " + accidents.get(accidents.size() - 1).type() + " at tick "
                + accidents.get(accidents.size() - 1).tick(), Font.PLAIN, 52);
        g.setColor(Color.DARK_GRAY);
        fitted(g, nearMisses(), Font.PLAIN, 68);
    }

    /**
     * The header's last line: each near-miss measure's least value so far, in its unit ("never" while
     * unmet), and the least ρ so far over the accident types measured in metres. Reported beside
     * accidents, never counted as one.
     */
    String nearMisses() {
        if (run().tick() < 0) {
            return "closest so far: nothing yet";
        }
        NearMisses watched = run().nearMisses();
        StringBuilder s = new StringBuilder("closest so far: ");
        for (NearMiss m : NearMiss.values()) {
            s.append(m.ordinal() == 0 ? "" : " · ").append(NearMissText.shortName(m)).append(' ')
                    .append(NearMissText.value(m, watched.least(m), m == NearMiss.TIME_TO_COLLISION ? 1 : 2));
        }
        AccidentType least = null;
        for (AccidentType t : AccidentType.values()) {
            if (t != AccidentType.TIMEOUT && (least == null || watched.robustness(t) < watched.robustness(least))) {
                least = t;
            }
        }
        return s.append(" · least ρ ").append(NearMissText.rho(least, watched.robustness(least), 2))
                .append(" (").append(least.label()).append(')').toString();
    }

    /** Draws a header line in 12 points, smaller (down to 9) if the pane is narrow, cut short only if even that is too wide. */
    private void fitted(Graphics2D g, String text, int style, int baseline) {
        int room = base.getWidth() - 16;
        int points = 12;
        g.setFont(new Font(Font.SANS_SERIF, style, points));
        while (points > 9 && g.getFontMetrics().stringWidth(text) > room) {
            g.setFont(new Font(Font.SANS_SERIF, style, --points));
        }
        while (g.getFontMetrics().stringWidth(text) > room && text.length() > 2) {
            text = text.substring(0, text.length() - 2) + "…";
        }
        g.drawString(text, 8, baseline);
    }

    /** What the controller's observation carried this tick, by the sensors it took. */
    String observed() {
        Set<Sensor> taken = run().telemetry().sensors();
        if (taken.isEmpty()) {
            return "observes no sensor (pose, map, Target, signals)";
        }
        List<String> parts = new java.util.ArrayList<>();
        boolean started = run().tick() >= 0;
        Observation sees = run().telemetry().observation();
        if (taken.contains(Sensor.RADAR)) {
            parts.add(started ? count(sees.traffic().size(), "radar track") : "radar tracks");
        }
        if (taken.contains(Sensor.OBSTACLES)) {
            parts.add(started ? count(sees.obstacles().size(), "obstacle") : "obstacles");
        }
        if (taken.contains(Sensor.CAMERA)) {
            parts.add("camera");
        }
        if (taken.contains(Sensor.LIDAR)) {
            parts.add("LIDAR");
        }
        return "observes " + String.join(" · ", parts);
    }

    private static String count(int n, String thing) {
        return n + " " + thing + (n == 1 ? "" : "s");
    }

    /** The header's second line: the car's state while the run goes on, how it ended once it has. */
    String status() {
        if (run().detector().outcome() != null) {
            return "Run over: " + OutcomeText.of(run().detector().outcome(), run().detector().ticks(), run().detector().accidents());
        }
        Vehicle car = run().telemetry().car();
        SelfReport said = run().telemetry().selfReport();
        // a controller that names no stage of its own is described by whether it says it overtakes
        String stage = said.stage() != null ? said.stage() : said.overtaking() ? "overtaking" : "not overtaking";
        return String.format(Locale.ROOT, "%s · %.1f km/h · lane %s · %s%s%s · steered by %s · speed set by %s",
                run().tick() < 0 ? "not started (press Play or Step)" : "tick " + run().tick(), car.speed() * 18,
                said.lane() == null ? Compass.nearest(car.heading()) : said.lane(),
                stage.toLowerCase(Locale.ROOT).replace('_', ' '),
                said.crossingJunction() ? " · crossing a junction" : "", said.waitingAtJunction() ? " · waiting" : "",
                said.steeredBy() == null ? "nothing yet" : said.steeredBy(), said.limitedBy() == null ? "nothing"
                        : said.limitedBy());
    }

    /**
     * The standard camera's reach (shaded fan) and the samples where its rays meet a marking (yellow
     * dots), and the standard LIDAR's reach (outlined half disc) and the rays of its sweep that hit
     * something, each where the controller took it: as the world offers them from where the car stands.
     * A controller that works from its own processing of them (the builtin car's degraded camera under
     * a camera fault) may have seen otherwise.
     */
    private void sensors(Graphics2D g, Vehicle body, Observation sees, Set<Sensor> taken) {
        if (taken.contains(Sensor.CAMERA)) {
            g.setColor(CAMERA);
            g.fill(fan(body.x(), body.y(), body.heading(), 45, CAMERA_RANGE));
        }
        if (taken.contains(Sensor.LIDAR)) {
            g.setColor(LIDAR);
            g.setStroke(new BasicStroke(1.5f / scale));
            g.draw(fan(body.x(), body.y(), body.heading(), 90, LIDAR_RANGE));
            g.setStroke(new BasicStroke(0.8f / scale));
            for (int h = 0; h < sees.lidarHits(); h++) {
                g.draw(new java.awt.geom.Line2D.Double(body.x(), body.y(), sees.lidarHitX(h), sees.lidarHitY(h)));
            }
        }
        if (!taken.contains(Sensor.CAMERA)) {
            return;
        }
        double r = 1.5 / scale;
        for (int h = 0; h < sees.cameraHits(); h++) {
            Ellipse2D dot = new Ellipse2D.Double(sees.cameraHitX(h) - r, sees.cameraHitY(h) - r, 2 * r, 2 * r);
            g.setColor(CAMERA_HIT);
            g.fill(dot);
            g.setColor(Color.BLACK);
            g.setStroke(new BasicStroke(0.5f / scale));
            g.draw(dot);
        }
    }

    /**
     * The objects the controller's sensors reported, over the bodies: each LIDAR obstacle outlined, each
     * radar track a dot at its front with a line to where it will be in a second at its speed.
     */
    private void reported(Graphics2D g, Observation sees, Set<Sensor> taken) {
        g.setColor(SENSED);
        if (taken.contains(Sensor.OBSTACLES)) {
            g.setStroke(new BasicStroke(2f / scale));
            for (Box b : sees.obstacles()) {
                g.draw(MapShapes.polygon(b));
            }
        }
        if (!taken.contains(Sensor.RADAR)) {
            return;
        }
        double r = 3.0 / scale;
        double ticks = 1 / Dimensions.TICK_SECONDS;
        g.setStroke(new BasicStroke(2f / scale));
        for (Vehicle v : sees.traffic()) {
            g.draw(new java.awt.geom.Line2D.Double(v.x(), v.y(), v.x() + v.headingDx() * v.speed() * ticks,
                    v.y() + v.headingDy() * v.speed() * ticks));
            g.fill(new Ellipse2D.Double(v.x() - r, v.y() - r, 2 * r, 2 * r));
        }
    }

    /** A circular sector from (x, y) spanning {@code half} degrees either side of {@code bearing}. */
    static Path2D fan(double x, double y, double bearing, double half, double range) {
        Path2D.Double p = new Path2D.Double();
        p.moveTo(x, y);
        for (double a = -half; a <= half + 1e-9; a += 5) {
            p.lineTo(x + range * Bearing.dx(bearing + a), y + range * Bearing.dy(bearing + a));
        }
        p.closePath();
        return p;
    }

    private void body(Graphics2D g, Vehicle v, Color fill) {
        var shape = MapShapes.polygon(v.footprint());
        g.setColor(fill);
        g.fill(shape);
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(1f / scale));
        g.draw(shape);
    }

    private void accidents(Graphics2D g, List<Accident> accidents) {
        g.setStroke(new BasicStroke(2.5f));
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 11));
        for (Accident a : accidents) {
            double px = a.x() * scale;
            double py = HEADER + a.y() * scale;
            g.setColor(ACCIDENT);
            g.draw(new Ellipse2D.Double(px - 9, py - 9, 18, 18));
            tag(g, a.type().name() + " t=" + a.tick(), px + 11, py - 6);
        }
    }

    /** Text on a white tag edged in the accident's red, so it reads on grass, asphalt and cars alike. */
    private static void tag(Graphics2D g, String text, double x, double baseline) {
        FontMetrics fm = g.getFontMetrics();
        RoundRectangle2D box = new RoundRectangle2D.Double(x - 3, baseline - fm.getAscent() - 1,
                fm.stringWidth(text) + 6, fm.getAscent() + fm.getDescent() + 2, 5, 5);
        g.setColor(Color.WHITE);
        g.fill(box);
        g.setColor(ACCIDENT);
        g.setStroke(new BasicStroke(1.2f));
        g.draw(box);
        g.drawString(text, (float) x, (float) baseline);
        g.setStroke(new BasicStroke(2.5f));
    }
}
