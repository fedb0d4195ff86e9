package sitcov.coverage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

class BinsTest {
    private final Bins c1 = GridDefinition.paper().bins().get(0);
    private final Bins c2 = GridDefinition.paper().bins().get(1);

    @Test
    void binsAreHalfOpenAtTheirLowerEdge() {
        assertEquals(0, c1.of(1.01));
        assertEquals(0, c1.of(6.0099));
        assertEquals(1, c1.of(6.01));
        assertEquals(5, c1.of(26.01));
        assertEquals(5, c1.of(200), "no parked car (200) is in the open top bin");
        assertEquals(2, c2.of(80));
    }

    @Test
    void valuesOutsideEveryBinAreInvalidNotFoldedIntoAnEndBin() {
        assertEquals(Bins.INVALID, c1.of(1.0));
        assertEquals(Bins.INVALID, c2.of(240));
        assertEquals(Bins.INVALID, c2.of(-0.1));
        assertEquals(Bins.INVALID, c2.of(Double.NaN));
        GridDefinition grid = GridDefinition.paper();
        assertEquals(Bins.INVALID, grid.cellOf(new double[] {0.5, 10, 10}));
        CoverageGrid counts = new CoverageGrid(grid);
        counts.add(Bins.INVALID);
        assertEquals(1, counts.invalid());
        assertEquals(0, counts.covered());
    }

    @Test
    void cellsNumberTheBinsWithTheFirstCriterionSlowest() {
        GridDefinition grid = GridDefinition.paper();
        assertEquals(216, grid.cells());
        int cell = grid.cellOf(new double[] {12, 130, 5});
        assertEquals((2 * 6 + 3) * 6 + 0, cell);
        assertEquals(2, grid.binOf(cell, 0));
        assertEquals(3, grid.binOf(cell, 1));
        assertEquals(0, grid.binOf(cell, 2));
    }

    @Test
    void theCommittedPaperGridFileIsThePaperGrid() throws Exception {
        assertEquals(GridDefinition.paper(), GridDefinition.read(Path.of("experiments", "paper-grid.txt")));
    }

    @Test
    void aMalformedGridFileNamesTheLineAndWhatWasExpected() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> GridDefinition.parse(
                List.of("sitcov-grid 1", "criterion start-target 0 40 30"), "g.txt"));
        assertTrue(e.getMessage().startsWith("g.txt:2: ") && e.getMessage().contains("must increase"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> GridDefinition.parse(
                List.of("sitcov-grid 1", "criterion speed 0 1"), "g.txt"));
        assertTrue(e.getMessage().contains("unknown criterion 'speed'"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> GridDefinition.parse(List.of("criterion start-target 0 1"), "g"));
    }

    @Test
    void aCellCountsAsCoveredOnceAndReportsOnlyTheFirstMap() {
        CoverageGrid grid = new CoverageGrid(GridDefinition.paper());
        assertTrue(grid.add(7));
        assertEquals(false, grid.add(7));
        assertEquals(1, grid.covered());
        assertEquals(2, grid.count(7));
    }
}
