package sitcov.faults;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

class FaultSetTest {
    private static Set<Integer> ids(String text) {
        return FaultSet.parse(text).stream().map(Fault::id).collect(Collectors.toSet());
    }

    @Test
    void paperNamesTheSevenFaultsOfTable1() {
        assertEquals(Set.of(2, 4, 8, 10, 12, 17, 18), ids("PAPER"));
    }

    @Test
    void allAndNoneAreEveryFaultAndNoFault() {
        assertEquals(20, ids("ALL").size());
        assertTrue(ids("NONE").isEmpty());
        assertEquals(Set.of(), ids("none"));
    }

    @Test
    void idsAndRangesAddUp() {
        assertEquals(Set.of(0, 8, 9, 10, 11, 12, 13, 19), ids("0,8-13, 19"));
    }

    @Test
    void exclusionsRemoveWhatCameBefore() {
        Set<Integer> expected = Stream.iterate(1, i -> i + 1).limit(19).collect(Collectors.toSet());
        assertEquals(expected, ids("ALL,-0"));
        assertEquals(Set.of(2, 4, 12, 17, 18), ids("PAPER,-8-10"));
    }

    @Test
    void unknownIdsAreRefusedWithTheValidList() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FaultSet.parse("3,20"));
        assertTrue(e.getMessage().contains("'20'") && e.getMessage().contains("0-19"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> FaultSet.parse("seven"));
        assertThrows(IllegalArgumentException.class, () -> FaultSet.parse(""));
        assertThrows(IllegalArgumentException.class, () -> FaultSet.parse("13-8"));
        assertThrows(IllegalArgumentException.class, () -> FaultSet.parse("1,,2"));
    }

    @Test
    void formattingGivesBackAnEquivalentShortText() {
        assertEquals("NONE", FaultSet.format(EnumSet.noneOf(Fault.class)));
        assertEquals("ALL", FaultSet.format(EnumSet.allOf(Fault.class)));
        assertEquals("PAPER", FaultSet.format(FaultSet.paper()));
        assertEquals("0,8-13,19", FaultSet.format(FaultSet.parse("19,8-13,0")));
    }
}
