package sitcov.viewer;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.GridLayout;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSlider;
import javax.swing.Timer;

/**
 * The live viewer (the paper's Fig. 1, MASON's console in spirit): one pane per run — the run and,
 * with a fault, its fault-free twin beside it — stepped together; play, pause, step, step back
 * (from checkpoints the runs keep), speed and restart. It owns the runs and steps them; the model never calls it.
 */
public final class ViewerWindow {
    /** Frames a second while playing; the slider sets how many ticks each frame advances. */
    private static final int FRAME_MILLIS = 40;
    /** Pixels between two panes. */
    static final int GAP = 8;
    /**
     * Room the window needs beyond its panes: title bar, the row of controls, borders. A generous
     * guess made before any window exists, so the scale can be chosen before the runs are drawn.
     */
    static final Dimension CHROME = new Dimension(40, 130);

    private final Supplier<List<RunPainter>> fresh;
    private final List<RunPainter> painters = new ArrayList<>();
    private final JPanel panes = new JPanel();
    private final JSlider speed = new JSlider(1, 20, 1);
    private final JButton play = new JButton("Play");
    private final Timer timer;

    /** {@code fresh} makes the runs from their start (again on restart). */
    public ViewerWindow(Supplier<List<RunPainter>> fresh) {
        this.fresh = fresh;
        this.timer = new Timer(FRAME_MILLIS, e -> advance(speed.getValue()));
        restart();
    }

    /** The screen's usable area (without task bars and docks), where the window must fit. */
    public static Rectangle usableScreen() {
        return GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
    }

    /**
     * The largest scale (pixels a metre, from {@code largest} down to 1) at which a window of
     * {@code panes} panes fits in {@code usable}; at 1 it may still not fit, and then it scrolls.
     */
    public static int scaleFor(Dimension usable, int panes, int largest) {
        for (int scale = largest; scale > 1; scale--) {
            Dimension window = windowSize(panes, scale);
            if (window.width <= usable.width && window.height <= usable.height) {
                return scale;
            }
        }
        return 1;
    }

    /** The window's size with {@code panes} panes side by side at {@code scale}. */
    static Dimension windowSize(int panes, int scale) {
        Dimension pane = RunPainter.paneSize(scale);
        return new Dimension(panes * pane.width + (panes - 1) * GAP + CHROME.width, pane.height + CHROME.height);
    }

    /** The panes side by side as the window shows them, painted off-screen into one picture. */
    public static java.awt.image.BufferedImage frame(List<RunPainter> painters) {
        int width = -GAP;
        int height = 0;
        for (RunPainter p : painters) {
            width += p.size().width + GAP;
            height = Math.max(height, p.size().height);
        }
        var image = new java.awt.image.BufferedImage(Math.max(1, width), Math.max(1, height),
                java.awt.image.BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setColor(java.awt.Color.WHITE);
            g.fillRect(0, 0, image.getWidth(), image.getHeight());
            int x = 0;
            for (RunPainter p : painters) {
                Graphics2D pane = (Graphics2D) g.create(x, 0, p.size().width, p.size().height);
                p.paint(pane);
                pane.dispose();
                x += p.size().width + GAP;
            }
        } finally {
            g.dispose();
        }
        return image;
    }

    public void show() {
        JFrame frame = new JFrame("sitcov view");
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        JPanel controls = new JPanel(new FlowLayout(FlowLayout.LEFT));
        play.addActionListener(e -> toggle());
        JButton step = new JButton("Step");
        step.addActionListener(e -> advance(1));
        JButton back = new JButton("Back");
        back.addActionListener(e -> back());
        JButton restart = new JButton("Restart");
        restart.addActionListener(e -> restart());
        controls.add(play);
        controls.add(back);
        controls.add(step);
        controls.add(restart);
        controls.add(new JLabel("ticks a frame"));
        speed.setMajorTickSpacing(5);
        speed.setPaintLabels(true);
        controls.add(speed);
        frame.getContentPane().add(controls, BorderLayout.NORTH);
        frame.getContentPane().add(new JScrollPane(panes), BorderLayout.CENTER);
        frame.pack();
        Rectangle usable = usableScreen();
        frame.setSize(Math.min(frame.getWidth(), usable.width), Math.min(frame.getHeight(), usable.height));
        frame.setLocation(usable.x, usable.y);
        frame.setVisible(true);
    }

    private void toggle() {
        if (timer.isRunning()) {
            timer.stop();
            play.setText("Play");
        } else {
            timer.start();
            play.setText("Pause");
        }
    }

    /** Steps every run {@code ticks} ticks (a run that ended stays as it ended). */
    void advance(int ticks) {
        boolean any = false;
        for (RunPainter p : painters) {
            for (int i = 0; i < ticks; i++) {
                if (!p.history().step()) {
                    break;
                }
                any = true;
            }
        }
        panes.repaint();
        if (!any && timer.isRunning()) {
            toggle();
        }
    }

    /** Steps every run back a tick, where its controller can be copied (the builtin car's can). */
    void back() {
        if (timer.isRunning()) {
            toggle();
        }
        for (RunPainter p : painters) {
            p.history().stepBack();
        }
        panes.repaint();
    }

    void restart() {
        painters.clear();
        painters.addAll(fresh.get());
        panes.removeAll();
        panes.setLayout(new GridLayout(1, painters.size(), GAP, 0));
        for (RunPainter p : painters) {
            panes.add(pane(p));
        }
        panes.revalidate();
        panes.repaint();
    }

    List<RunPainter> painters() {
        return painters;
    }

    private static JComponent pane(RunPainter painter) {
        JComponent c = new JComponent() {
            @Override
            protected void paintComponent(Graphics g) {
                painter.paint((Graphics2D) g);
            }
        };
        Dimension size = painter.size();
        c.setPreferredSize(size);
        return c;
    }
}
