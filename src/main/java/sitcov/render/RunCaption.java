package sitcov.render;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.Line2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import sitcov.oracle.AccidentType;
import sitcov.oracle.RunResult;

/**
 * The caption strip of a run picture, in pixels: the seeds, the outcome, the accidents and the
 * least robustness ρ; a row naming the path colours, the footprints, the accident markers and the
 * closest approaches' dot; and the map's own legend.
 * Rows that do not fit the picture's width fall back to shorter names.
 */
final class RunCaption {
    private static final String FOOTPRINTS = "car every 10 ticks, at the end";

    private final Graphics2D g;
    private final MapStyle style;

    RunCaption(Graphics2D g, MapStyle style) {
        this.g = g;
        this.style = style;
    }

    /** Seeds, outcome, accident counts; the run's legend; the map's legend. */
    void paint(RunResult result, int top, int width, int bottom) {
        int pad = MapStyle.padding(style.scale());
        int line = MapStyle.lineHeight(style.scale());
        g.setColor(MapStyle.CAPTION);
        g.fillRect(0, top, width, bottom - top);
        g.setColor(MapStyle.TEXT);
        g.setFont(style.font(Font.BOLD));
        FontMetrics bold = g.getFontMetrics();
        int baseline = top + pad + bold.getAscent();
        String title = "seed " + result.externalSeed() + " · internal seed " + result.internalSeed();
        g.drawString(title, pad, baseline);
        g.setFont(style.font(Font.PLAIN));
        FontMetrics plain = g.getFontMetrics();
        String summary = summary(result, false);
        if (pad + bold.stringWidth(title) + plain.stringWidth(summary) > width - pad) {
            summary = summary(result, true);
        }
        g.drawString(summary, pad + bold.stringWidth(title), baseline);
        BufferedImage scratch = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        Graphics2D measure = scratch.createGraphics();
        measure.setRenderingHints(g.getRenderingHints());
        int compactness = 0;
        while (compactness < 2 && new RunCaption(measure, style).legend(pad, 0, compactness) > width) {
            compactness++;
        }
        measure.dispose();
        legend(pad, top + pad + line + line / 2, compactness);
        new MapLegend(g, style).paint(top + pad + 2 * line, width);
    }

    private static String summary(RunResult result, boolean compact) {
        StringBuilder s = new StringBuilder("   ").append(result.outcome()).append(" after ").append(result.ticks())
                .append(" ticks · ").append(result.accidents().size())
                .append(result.accidents().size() == 1 ? " accident" : " accidents");
        List<String> counts = new ArrayList<>();
        for (Map.Entry<AccidentType, Long> e : result.countsByType().entrySet()) {
            if (e.getValue() > 0) {
                counts.add(e.getValue() + " " + (compact ? e.getKey().label() : e.getKey()));
            }
        }
        if (!counts.isEmpty()) {
            s.append(compact ? " (" : ": ").append(String.join(", ", counts)).append(compact ? ")" : "");
        }
        int excused = result.excusedContacts().values().stream().mapToInt(Integer::intValue).sum();
        if (excused > 0 && !compact) {
            s.append(" · ").append(excused).append(excused == 1 ? " excused contact" : " excused contacts");
        }
        leastRho(result).ifPresent(rho -> s.append(" · least ρ ").append(rho));
        return s.append(compact ? "" : " · grid 10 m").toString();
    }

    /**
     * The least ρ over the accident types measured in metres, and its type: how near the run came to
     * its nearest accident (below 0: it had it). TIMEOUT's ρ counts ticks, so it is not compared.
     */
    static java.util.Optional<String> leastRho(RunResult result) {
        AccidentType least = null;
        for (AccidentType t : AccidentType.values()) {
            double v = result.margins().robustness(t);
            if (t != AccidentType.TIMEOUT && !Double.isNaN(v)
                    && (least == null || v < result.margins().robustness(least))) {
                least = t;
            }
        }
        if (least == null || Double.isInfinite(result.margins().robustness(least))) {
            return java.util.Optional.empty();
        }
        return java.util.Optional.of(NearMissText.rho(least, result.margins().robustness(least), 2) + " (" + least.label() + ")");
    }

    /**
     * Path colours, footprints and accident markers, in a row from pixel {@code x} centred on
     * {@code mid}; returns the x where the row ends.
     */
    int legend(int x, int mid, int compactness) {
        boolean compact = compactness >= 2;
        g.setFont(style.smallFont());
        FontMetrics fm = g.getFontMetrics();
        int gap = Math.max(3, MapStyle.padding(style.scale()) / 2);
        int sym = Math.max(10, fm.getAscent());
        int baseline = mid + (fm.getAscent() - fm.getDescent()) / 2;
        Color[] paths = {RunMarks.DRIVING, RunMarks.CROSSING, RunMarks.OVERTAKING};
        String[] names = compact ? new String[] {"driving", "crossing", "overtaking"}
                : new String[] {"path: driving", "crossing a junction", "overtaking"};
        for (int i = 0; i < 3; i++) {
            g.setColor(Color.BLACK);
            g.setStroke(new BasicStroke(5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            g.draw(new Line2D.Double(x + 2, mid, x + 2 * sym - 2, mid));
            g.setColor(paths[i]);
            g.setStroke(new BasicStroke(3f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            g.draw(new Line2D.Double(x + 2, mid, x + 2 * sym - 2, mid));
            x = name(names[i], x + 2 * sym + gap, baseline, fm, gap);
        }
        RunMarks marks = new RunMarks(g, style);
        g.setColor(MapStyle.ASPHALT);
        g.fillRect(x, mid - sym / 2 - 2, 2 * sym + 4, sym + 4);
        g.setColor(Color.WHITE);
        g.setStroke(new BasicStroke(1f));
        g.drawRect(x + 2, mid - sym / 2, sym - 2, sym);
        g.setColor(RunMarks.FINAL_FILL);
        g.fillRect(x + sym + 2, mid - sym / 2, sym - 1, sym);
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(2f));
        g.drawRect(x + sym + 2, mid - sym / 2, sym - 1, sym);
        x = name(compact ? "car, at end" : FOOTPRINTS, x + 2 * sym + 4 + gap, baseline, fm, gap);
        for (AccidentType type : AccidentType.values()) {
            marks.marker(type, x + sym / 2.0, mid, sym / 2.0);
            x = name(compactness >= 1 ? type.label() : type.name(), x + sym + gap, baseline, fm, gap);
        }
        RunMarks.closestDot(g, x + sym / 2.0, mid, Math.max(3, sym / 3.0));
        return name(compactness >= 1 ? "closest" : "closest approach", x + sym + gap, baseline, fm, gap);
    }

    private int name(String text, int x, int baseline, FontMetrics fm, int gap) {
        g.setColor(MapStyle.TEXT);
        g.drawString(text, x, baseline);
        return x + fm.stringWidth(text) + 3 * gap;
    }
}
