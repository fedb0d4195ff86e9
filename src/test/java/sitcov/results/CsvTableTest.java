package sitcov.results;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CsvTableTest {
    @Test
    void aColumnIsReadByItsNameWhereverTheHeaderPutsIt(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("t.csv");
        Files.writeString(file, "b,a\n2,1\n");
        CsvTable t = CsvTable.read(file);
        assertEquals("1", t.get(t.rows().get(0), "a"));
        assertEquals("2", t.get(t.rows().get(0), "b"));
    }

    @Test
    void aColumnTheHeaderLacksFailsLoudlyInsteadOfReadingAsEmpty(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("t.csv");
        Files.writeString(file, "a,b\n1,2\n");
        CsvTable t = CsvTable.read(file);
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> t.get(t.rows().get(0), "c"));
        assertTrue(e.getMessage().contains("no column 'c'"), e.getMessage());
    }
}
