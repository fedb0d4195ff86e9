package sitcov.results;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ColumnsTest {
    private static final Columns TABLE = Columns.of("replication", "driver", "ticks");

    @Test
    void aRowIsWrittenInTheColumnListsOrderWhateverOrderItsValuesAreGiven() {
        assertEquals("replication,driver,ticks", TABLE.header());
        assertEquals("2,random,40\n", TABLE.row().set("ticks", 40).set("replication", 2).set("driver", "random").line());
    }

    @Test
    void aRowMissingAValueIsNotWritten() {
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> TABLE.row().set("replication", 2).set("ticks", 40).line());
        assertTrue(e.getMessage().contains("driver"), e.getMessage());
    }

    @Test
    void aFileIsReadByItsHeadersNames() {
        Columns.Layout layout = TABLE.layout("ticks,replication,driver", "t.csv", "fix it");
        Columns.Line line = layout.split("40,2,random");
        assertEquals(2, line.integer("replication"));
        assertEquals("random", line.get("driver"));
        assertEquals(40L, line.longValue("ticks"));
    }

    @Test
    void aHeaderLackingOrAddingAColumnIsRefusedNamingItAndTheFix() {
        IllegalArgumentException missing = assertThrows(IllegalArgumentException.class,
                () -> TABLE.layout("replication,driver", "old/t.csv", "run it again"));
        assertTrue(missing.getMessage().startsWith("old/t.csv:1: the header lacks the column 'ticks' this sitcov reads"),
                missing.getMessage());
        assertTrue(missing.getMessage().endsWith("; run it again"), missing.getMessage());
        IllegalArgumentException unknown = assertThrows(IllegalArgumentException.class,
                () -> TABLE.layout("replication,driver,ticks,speed", "new/t.csv", "run it again"));
        assertTrue(unknown.getMessage().contains("has the column 'speed' this sitcov does not know"), unknown.getMessage());
        IllegalArgumentException twice = assertThrows(IllegalArgumentException.class,
                () -> TABLE.layout("replication,driver,ticks,ticks", "t.csv", "run it again"));
        assertTrue(twice.getMessage().contains("has the column 'ticks' twice"), twice.getMessage());
    }

    @Test
    void aLineWithTheWrongNumberOfValuesIsRefused() {
        Columns.Layout layout = TABLE.layout(TABLE.header(), "t.csv", "fix it");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> layout.split("2,random"));
        assertEquals("expected 3 columns, found 2", e.getMessage());
    }

    @Test
    void aRowOfAKindThatLacksSomeColumnsLeavesThemBlankOnlyWhenAskedTo() {
        assertEquals("2,,", TABLE.row().set("replication", 2).blankRest().text());
        assertThrows(IllegalStateException.class, () -> TABLE.row().set("replication", 2).text());
    }
}
