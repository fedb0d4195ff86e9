package sitcov.world;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The hand-built fixtures must themselves keep every rule, or tests built on them prove little. */
class SituationsTest {

    @Test
    void theStraightRoadWithAParkedCarKeepsEveryRule() {
        Layout layout = Situations.straight(List.of(Situations.parkedInEastboundLane(0, 100)));
        assertEquals(List.of(), Invariants.violations(layout));
    }

    @Test
    void theTeeKeepsEveryRule() {
        assertEquals(List.of(), Invariants.violations(Situations.tee()));
    }
}
