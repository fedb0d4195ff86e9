package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.oracle.Failure;

class RequirementTest {
    @Test
    void eachRequirementOfAnAccidentTypeIsViolatedByThatAccidentAlone() {
        for (Requirement r : Requirement.values()) {
            if (r == Requirement.CONTROLLER) {
                continue;
            }
            Failure own = Failure.of(r.robustness().orElseThrow());
            assertTrue(r.violatedBy(Set.of(own)), r + " by " + own);
            assertFalse(r.violatedBy(EnumSet.complementOf(EnumSet.of(own))), r + " by every other failure");
        }
    }

    @Test
    void theControllersRequirementIsViolatedByEitherOfItsFailuresAndByNoAccident() {
        assertTrue(Requirement.CONTROLLER.violatedBy(Set.of(Failure.CONTROLLER_TIMEOUT)));
        assertTrue(Requirement.CONTROLLER.violatedBy(Set.of(Failure.CONTROLLER_ERROR)));
        assertFalse(Requirement.CONTROLLER.violatedBy(EnumSet.range(Failure.CLASHWITHOBSTACLE, Failure.TIMEOUT)));
    }

    @Test
    void everyFailureViolatesExactlyOneRequirement() {
        for (Failure f : Failure.values()) {
            assertEquals(1, java.util.Arrays.stream(Requirement.values()).filter(r -> r.violatedBy(Set.of(f))).count(), f.name());
        }
    }
}
