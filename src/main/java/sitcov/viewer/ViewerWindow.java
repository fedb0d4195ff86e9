package sitcov.viewer;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
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
 * with a fault, its fault-free twin beside it — stepped together; play, pause, step, speed and
 * restart. It owns the runs and steps them; the model never calls it.
 */
public final class ViewerWindow {
    /** Frames a second while playing; the slider sets how many ticks each frame advances. */
    private static final int FRAME_MILLIS = 40;

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

    public void show() {
        JFrame frame = new JFrame("sitcov view");
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        JPanel controls = new JPanel(new FlowLayout(FlowLayout.LEFT));
        play.addActionListener(e -> toggle());
        JButton step = new JButton("Step");
        step.addActionListener(e -> advance(1));
        JButton restart = new JButton("Restart");
        restart.addActionListener(e -> restart());
        controls.add(play);
        controls.add(step);
        controls.add(restart);
        controls.add(new JLabel("ticks a frame"));
        speed.setMajorTickSpacing(5);
        speed.setPaintLabels(true);
        controls.add(speed);
        frame.getContentPane().add(controls, BorderLayout.NORTH);
        frame.getContentPane().add(new JScrollPane(panes), BorderLayout.CENTER);
        frame.pack();
        frame.setSize(Math.min(frame.getWidth(), 1600), Math.min(frame.getHeight() + 40, 1000));
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
                if (!p.run().step()) {
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

    void restart() {
        painters.clear();
        painters.addAll(fresh.get());
        panes.removeAll();
        panes.setLayout(new GridLayout(1, painters.size(), 8, 0));
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
