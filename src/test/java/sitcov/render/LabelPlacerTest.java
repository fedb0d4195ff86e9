package sitcov.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;

class LabelPlacerTest {
    @Test
    void tenLabelsOnOnePointAreSpreadSoNoneOverlapsAnotherAndAllStayInThePicture() {
        BufferedImage image = new BufferedImage(600, 300, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        Rectangle2D bounds = new Rectangle2D.Double(0, 0, 600, 300);
        LabelPlacer placer = new LabelPlacer(g, new MapStyle(6), bounds);
        Rectangle2D marker = new Rectangle2D.Double(290, 140, 20, 20);
        placer.reserve(marker);
        for (int i = 0; i < 10; i++) {
            placer.place("label number " + i + " t=4999", 300, 150, 13, 11, Color.RED);
        }
        g.dispose();
        List<Rectangle2D> placed = placer.placed();
        assertEquals(10, placed.size());
        for (int i = 0; i < placed.size(); i++) {
            assertTrue(bounds.contains(placed.get(i)), placed.get(i) + " sticks out of the picture");
            assertFalse(placed.get(i).intersects(marker), "label " + i + " covers the marker");
            for (int j = i + 1; j < placed.size(); j++) {
                assertFalse(placed.get(i).intersects(placed.get(j)), "labels " + i + " and " + j + " overlap");
            }
        }
    }
}
