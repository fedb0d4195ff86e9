package sitcov.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class ControllerChoiceTest {

    @Test
    void builtinIsTheBuiltinCar() {
        assertEquals(new ControllerChoice.Builtin(), ControllerChoice.parse(" builtin "));
    }

    @Test
    void execSplitsItsCommandAtSpacesAndKeepsQuotedSpaces() {
        assertEquals(new ControllerChoice.Exec(List.of("python3", "my controller.py", "--bug", "it's")),
                ControllerChoice.parse("exec:python3 'my controller.py'  --bug \"it's\""));
    }

    @Test
    void anythingElseIsRefusedWithWhatIsAccepted() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ControllerChoice.parse("python3 x.py"));
        assertTrue(e.getMessage().startsWith("a controller is builtin, builtin:FAULTS"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> ControllerChoice.parse("exec:  "));
        assertThrows(IllegalArgumentException.class, () -> ControllerChoice.parse("exec:python3 'x.py"));
    }
}
