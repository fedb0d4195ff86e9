package sitcov.oracle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.util.Arrays;
import java.util.function.Function;
import org.junit.jupiter.api.Test;

class AccidentTypeTest {
    @Test
    void noTwoAccidentTypesShareAName() {
        for (Function<AccidentType, String> name : java.util.List.<Function<AccidentType, String>>of(
                AccidentType::column, AccidentType::word, AccidentType::label)) {
            assertEquals(AccidentType.values().length, Arrays.stream(AccidentType.values()).map(name).distinct().count());
        }
    }

    @Test
    void theCalibrationTablesNameIsOneWordAndTheColumnIsLowerCase() {
        for (AccidentType t : AccidentType.values()) {
            assertFalse(t.word().contains(" "), t.word());
            assertEquals(t.name().toLowerCase(java.util.Locale.ROOT), t.column());
        }
    }
}
