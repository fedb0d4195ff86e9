package sitcov.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Dimension;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.judge.LiveRun;
import sitcov.world.MapGenerator;

/** The window's size, worked out for a given screen without opening one. */
class ViewerWindowTest {
    private static final int LARGEST = 6;

    private static boolean fits(Dimension window, Dimension screen) {
        return window.width <= screen.width && window.height <= screen.height;
    }

    @Test
    void theWindowTakesTheLargestScaleAtWhichItFitsTheScreensUsableArea() {
        List<Dimension> screens = List.of(new Dimension(1366, 728), new Dimension(1920, 1040), new Dimension(1280, 760),
                new Dimension(1024, 560), new Dimension(3840, 2100));
        for (Dimension screen : screens) {
            for (int panes = 1; panes <= 2; panes++) {
                int scale = ViewerWindow.scaleFor(screen, panes, LARGEST);
                assertTrue(scale >= 1 && scale <= LARGEST);
                assertTrue(fits(ViewerWindow.windowSize(panes, scale), screen), screen + ", " + panes + " panes at " + scale);
                if (scale < LARGEST) {
                    assertTrue(!fits(ViewerWindow.windowSize(panes, scale + 1), screen), "a larger scale fits " + screen);
                }
            }
        }
        // two 200 m maps at 4 px/m are 1608 pixels wide; at 5, 2008: a 1920-pixel screen takes 4, a 1366 one 3
        assertEquals(4, ViewerWindow.scaleFor(new Dimension(1920, 1040), 2, LARGEST));
        assertEquals(3, ViewerWindow.scaleFor(new Dimension(1366, 728), 2, LARGEST));
    }

    @Test
    void aPaneIsTheSizeTheWindowReckonsWith() {
        RunPainter painter = new RunPainter(BuiltinRuns.live(MapGenerator.generate(1), 1, Set.of()), "test", 3);
        assertEquals(RunPainter.paneSize(3), painter.size());
    }

    @Test
    void backStepsEveryPaneATickBackToTheRunAsItWasThen() {
        java.util.function.Supplier<List<RunPainter>> runs = () -> List.of(
                new RunPainter(BuiltinRuns.live(MapGenerator.generate(1), 1, Set.of()), "fault-free", 1),
                new RunPainter(BuiltinRuns.live(MapGenerator.generate(1), 1, Set.of(sitcov.faults.Fault.CRAWL_DOUBLE_BRAKING)),
                        "fault 6", 1));
        ViewerWindow window = new ViewerWindow(runs);
        window.advance(60);
        window.back();
        window.back();
        ViewerWindow twin = new ViewerWindow(runs);
        twin.advance(58);
        for (int pane = 0; pane < 2; pane++) {
            LiveRun back = window.painters().get(pane).run();
            LiveRun then = twin.painters().get(pane).run();
            assertEquals(57, back.tick());
            assertEquals(then.record(), back.record());
            assertEquals(then.telemetry().car().x(), back.telemetry().car().x());
            assertEquals(then.telemetry().car().heading(), back.telemetry().car().heading());
        }
    }
}
