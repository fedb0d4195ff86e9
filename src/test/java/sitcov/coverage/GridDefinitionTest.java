package sitcov.coverage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

class GridDefinitionTest {
    /** Two criteria of unequal bin counts, so that a mix-up of strides or orders shows. */
    private final GridDefinition grid = GridDefinition.parse(List.of("sitcov-grid 1",
            "criterion start-target 0 40 80 120", "criterion target-obstacle 0 10"), "small");

    @Test
    void aCellOfBinsIsTheCellTheirValuesFallIn() {
        GridDefinition paper = GridDefinition.paper();
        // values in bins 2, 3 and 0 of the paper's criteria (experiments/README.md, "Situation coverage")
        assertEquals(paper.cellOf(new double[] {12, 130, 5}), paper.cellAt(2, 3, 0));
        assertEquals(paper.cellOf(new double[] {30, 239, 55}), paper.cellAt(5, 5, 5));
        assertEquals(grid.cellOf(new double[] {90, 3}), grid.cellAt(2, 0));
    }

    @Test
    void everyCellIsTheCellOfItsOwnBins() {
        GridDefinition paper = GridDefinition.paper();
        for (int cell = 0; cell < paper.cells(); cell++) {
            assertEquals(cell, paper.cellAt(paper.binOf(cell, 0), paper.binOf(cell, 1), paper.binOf(cell, 2)));
        }
    }

    @Test
    void aBinOutsideItsCriterionOrAWrongCountIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> grid.cellAt(3, 0));
        assertThrows(IllegalArgumentException.class, () -> grid.cellAt(0, -1));
        assertThrows(IllegalArgumentException.class, () -> grid.cellAt(0));
    }

    @Test
    void aCellsNeighboursDifferByOneBinInOneCriterion() {
        GridDefinition paper = GridDefinition.paper();
        for (int cell = 0; cell < paper.cells(); cell++) {
            Set<Integer> expected = new HashSet<>();
            for (int c = 0; c < 3; c++) {
                for (int step : new int[] {-1, 1}) {
                    int[] b = {paper.binOf(cell, 0), paper.binOf(cell, 1), paper.binOf(cell, 2)};
                    b[c] += step;
                    if (b[c] >= 0 && b[c] < 6) {
                        expected.add(paper.cellAt(b));
                    }
                }
            }
            Set<Integer> found = new HashSet<>();
            for (GridDefinition.Neighbour n : paper.neighbours(cell)) {
                found.add(n.cell());
                assertEquals(paper.binOf(cell, n.criterion()), n.bin());
                assertEquals(n.bin() + n.step(), paper.binOf(n.cell(), n.criterion()));
            }
            assertEquals(expected, found, "cell " + cell);
            assertEquals(expected.size(), paper.neighbours(cell).size(), "no neighbour twice");
        }
    }

    @Test
    void neighboursAreListedTheLastCriterionFirstAndTheLowerBinFirst() {
        // cell (1, 0): start-target bin 1 of 3, target-obstacle bin 0 of 1 (no neighbour in it)
        assertEquals(List.of(new GridDefinition.Neighbour(0, 1, -1, grid.cellAt(0, 0)),
                new GridDefinition.Neighbour(0, 1, 1, grid.cellAt(2, 0))), grid.neighbours(grid.cellAt(1, 0)));
        GridDefinition paper = GridDefinition.paper();
        assertEquals(List.of(2, 2, 1, 1, 0, 0), paper.neighbours(paper.cellAt(3, 3, 3)).stream()
                .map(GridDefinition.Neighbour::criterion).toList());
    }
}
