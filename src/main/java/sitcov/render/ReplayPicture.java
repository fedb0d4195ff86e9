package sitcov.render;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.Locale;
import sitcov.control.ControllerFactory;
import sitcov.faults.Activation;
import sitcov.judge.FaultVerdict;
import sitcov.judge.FaultyRuns;
import sitcov.judge.Simulator;
import sitcov.oracle.Accident;
import sitcov.oracle.RunResult;
import sitcov.world.WorldMap;

/**
 * A fault-free run and its faulty twin (same map, same internal seed) side by side, under a title
 * that names them and the verdict; on the faulty side a ring where the fault first changed what
 * the car did, and the first accident the fault-free run lacks ringed in red.
 */
public final class ReplayPicture {
    /** One run to draw: its trajectory and result. */
    public record Side(TrajectoryRecorder trajectory, RunResult result) {
    }

    private static final int TITLE = 64;
    static final Color EFFECT = new Color(0xFF8C00);
    static final Color NEW_ACCIDENT = new Color(0xD7263D);

    private final int scale;

    public ReplayPicture(int pixelsPerMetre) {
        this.scale = pixelsPerMetre;
    }

    /**
     * Both runs; {@code verdict} is one line (e.g. "FOUND by LEAVEROAD at tick 485"), {@code newAccident}
     * the first accident the fault-free run lacks, if any.
     */
    public BufferedImage render(WorldMap map, Side faultFree, Side faulty, Activation activation, String verdict,
                                java.util.Optional<Accident> newAccident) {
        return render(map, faultFree, faulty, new Titles("without the fault", String.format(Locale.ROOT,
                "with fault %d (%s)", activation.fault().id(), activation.fault().label()),
                "the same map and internal seed; the runs part where the fault first acts"),
                java.util.Optional.of(activation), verdict, newAccident);
    }

    /** What the picture's title says: over each side, and under them both. */
    public record Titles(String left, String right, String subtitle) {
        /** The titles of a variant that is a controller of its own beside the reference. */
        public static Titles ofVariant(sitcov.judge.Variant variant) {
            return new Titles("the reference", "variant " + variant.id() + " (" + variant.label() + ")",
                    "the same map and internal seed, each run replayed from its recorded commands");
        }
    }

    /** Both runs under {@code titles}; the faulty side's ring where {@code activation} says the fault first acted. */
    public BufferedImage render(WorldMap map, Side faultFree, Side faulty, Titles titles,
                                java.util.Optional<Activation> activation, String verdict,
                                java.util.Optional<Accident> newAccident) {
        RunRenderer renderer = new RunRenderer(scale);
        BufferedImage left = renderer.render(map, faultFree.trajectory(), faultFree.result());
        BufferedImage right = renderer.render(map, faulty.trajectory(), faulty.result(),
                highlights(faulty, activation, newAccident));
        int gap = 12;
        BufferedImage image = new BufferedImage(left.getWidth() + gap + right.getWidth(), TITLE + left.getHeight(),
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(MapStyle.CAPTION);
            g.fillRect(0, 0, image.getWidth(), image.getHeight());
            g.drawImage(left, 0, TITLE, null);
            g.drawImage(right, left.getWidth() + gap, TITLE, null);
            title(g, left.getWidth(), gap, titles, verdict);
        } finally {
            g.dispose();
        }
        return image;
    }

    /** One run alone under a title and a line beneath it, as a pair is drawn. */
    public BufferedImage render(WorldMap map, Side run, String title, String line) {
        BufferedImage alone = new RunRenderer(scale).render(map, run.trajectory(), run.result());
        BufferedImage image = new BufferedImage(alone.getWidth(), TITLE + alone.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(MapStyle.CAPTION);
            g.fillRect(0, 0, image.getWidth(), TITLE);
            g.drawImage(alone, 0, TITLE, null);
            g.setColor(MapStyle.TEXT);
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 18));
            g.drawString(title, 12, 26);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
            g.drawString(line, 12, 50);
        } finally {
            g.dispose();
        }
        return image;
    }

    /**
     * The faulty side's marks, drawn by {@link RunRenderer} so that their labels and the run's share
     * one placer: a ring where the fault first acted, and the first new accident singled out.
     */
    static RunRenderer.Highlights highlights(Side faulty, java.util.Optional<Activation> acted,
                                             java.util.Optional<Accident> newAccident) {
        java.util.List<RunRenderer.Ring> rings = new java.util.ArrayList<>();
        if (acted.isPresent() && acted.get().effective()) {
            Activation activation = acted.get();
            int i = faulty.trajectory().entryOf(activation.firstEffectiveTick());
            if (i >= 0) {
                rings.add(new RunRenderer.Ring(faulty.trajectory().x(i), faulty.trajectory().y(i), EFFECT,
                        "fault " + activation.fault().id() + " first acts, t=" + activation.firstEffectiveTick()));
            }
        }
        java.util.Optional<Accident> drawn = newAccident.filter(faulty.result().accidents()::contains);
        if (newAccident.isPresent() && drawn.isEmpty()) { // not one of the run's own: ring it on its own
            Accident a = newAccident.get();
            rings.add(new RunRenderer.Ring(a.x(), a.y(), NEW_ACCIDENT, "first new accident, t=" + a.tick()));
        }
        return new RunRenderer.Highlights(rings, drawn, NEW_ACCIDENT, "first new accident: ");
    }

    /** The verdict in one line, saying where the experiment stopped the faulty run. */
    public static String verdictLine(sitcov.judge.FaultVerdict verdict, sitcov.judge.FaultyRuns length) {
        return verdict.detection() + verdict.newAccident().map(a -> " by " + a.type() + " at tick " + a.tick())
                .orElse(verdict.newFailure().map(f -> " by " + f + " at tick " + (verdict.faultyRun().ticks() - 1)).orElse(""))
                + (length == sitcov.judge.FaultyRuns.UNTIL_VERDICT && verdict.newAccident()
                        .filter(a -> a.type() != sitcov.oracle.AccidentType.TIMEOUT).isPresent()
                        ? " (the experiment stopped this run there)" : ""); // a TIMEOUT is the run's own end
    }

    /** Runs the map without and with {@code verdict}'s fault (the faulty run to its end), each run {@code controller}'s, and draws both. */
    public BufferedImage render(WorldMap map, long internalSeed, sitcov.judge.FaultVerdict verdict,
                                sitcov.judge.FaultyRuns length, ControllerFactory controller) {
        TrajectoryRecorder free = new TrajectoryRecorder();
        RunResult faultFree = sitcov.judge.Simulator.run(map, internalSeed, java.util.Set.of(), free, controller).result();
        TrajectoryRecorder faulty = new TrajectoryRecorder();
        sitcov.faults.Fault fault = verdict.seededFault().orElseThrow();
        var record = sitcov.judge.Simulator.run(map, internalSeed, java.util.Set.of(fault), faulty, controller);
        return render(map, new Side(free, faultFree), new Side(faulty, record.result()),
                record.activations().get(fault.ordinal()), verdictLine(verdict, length), verdict.newAccident());
    }

    private void title(Graphics2D g, int half, int gap, Titles titles, String verdict) {
        g.setColor(MapStyle.TEXT);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 18));
        g.drawString(titles.left(), 12, 26);
        g.drawString(titles.right(), half + gap + 12, 26);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
        g.drawString(titles.subtitle(), 12, 50);
        g.drawString(verdict, half + gap + 12, 50);
    }
}
