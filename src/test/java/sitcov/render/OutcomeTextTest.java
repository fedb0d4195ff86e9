package sitcov.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.oracle.Accident;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Outcome;

class OutcomeTextTest {
    @Test
    void aRunThatReachedTheTargetSaysAtWhichTickItsLastTickWas() {
        assertEquals("Reached the Target at t=222", OutcomeText.of(Outcome.TARGET_REACHED, 223, List.of()));
    }

    @Test
    void aTimeoutIsNamedOnceAndTheOtherAccidentsAreListedAfterIt() {
        List<Accident> accidents = List.of(new Accident(52, AccidentType.LEAVEROAD, 1, 1, -1),
                new Accident(60, AccidentType.CROSSCENTRELINE, 1, 1, -1),
                new Accident(70, AccidentType.LEAVEROAD, 1, 1, -1),
                new Accident(4999, AccidentType.TIMEOUT, 1, 1, -1));
        assertEquals("TIMEOUT at t=4999, the Target not reached · 3 accidents: LEAVEROAD at t=52, CROSSCENTRELINE at t=60 +1 more",
                OutcomeText.of(Outcome.TIMEOUT, 5000, accidents));
        assertEquals("Stopped at t=52, its verdict settled · accident: LEAVEROAD at t=52",
                OutcomeText.of(Outcome.STOPPED_AT_VERDICT, 53, accidents.subList(0, 1)));
    }
}
