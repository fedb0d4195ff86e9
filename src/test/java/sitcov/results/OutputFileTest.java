package sitcov.results;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class OutputFileTest {
    @TempDir
    Path dir;

    @Test
    void aNewFileIsReadableByOthersAndNoTemporaryFileIsLeft() throws Exception {
        Path file = dir.resolve("new.csv");
        OutputFile.writeString(file, "a,b\n");
        assertEquals("a,b\n", Files.readString(file));
        assertEquals("rw-r--r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
        try (Stream<Path> s = Files.list(dir)) {
            assertEquals(1, s.count());
        }
    }

    @Test
    void anOverwrittenFileKeepsItsMode() throws Exception {
        Path file = dir.resolve("private.csv");
        Files.writeString(file, "old");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-------"));
        OutputFile.writeString(file, "new");
        assertEquals("new", Files.readString(file));
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
    }

    @Test
    void writingThroughALinkReplacesTheFileItNamesAndKeepsTheLink() throws Exception {
        Path real = dir.resolve("real.png");
        Files.writeString(real, "old");
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), real);
        OutputFile.writeString(link, "new");
        assertTrue(Files.isSymbolicLink(link), "the link is still a link");
        assertEquals("new", Files.readString(real));
        Path dangling = Files.createSymbolicLink(dir.resolve("dangling.png"), dir.resolve("nowhere.png"));
        IOException e = assertThrows(IOException.class, () -> OutputFile.writeString(dangling, "x"));
        assertTrue(e.getMessage().contains("which does not exist"), e.getMessage());
        assertFalse(Files.exists(dir.resolve("nowhere.png")));
    }

    @Test
    void aDeviceIsWrittenIntoNotReplacedByARegularFile() throws Exception {
        Path devNull = Path.of("/dev/null");
        if (!Files.exists(devNull)) {
            return;
        }
        OutputFile.writeString(devNull, "discarded");
        assertFalse(Files.isRegularFile(devNull, LinkOption.NOFOLLOW_LINKS), "/dev/null must stay a device");
    }

    @Test
    void aFileNotCommittedLeavesTheTargetAsItWas() throws Exception {
        Path file = dir.resolve("keep.txt");
        Files.writeString(file, "good");
        try (OutputFile out = OutputFile.open(file)) {
            out.stream().write("half".getBytes());
        }
        assertEquals("good", Files.readString(file));
        try (Stream<Path> s = Files.list(dir)) {
            assertEquals(1, s.count(), "the temporary file is removed");
        }
    }

    @Test
    void aLinkAndTheFileItNamesAreOneFileEvenBeforeEitherIsWritten() throws Exception {
        Path target = dir.resolve("trace.csv");
        Path link = Files.createSymbolicLink(dir.resolve("picture.png"), Path.of("trace.csv"));
        assertTrue(OutputFile.sameFile(link, target), "a dangling link and its target");
        Files.writeString(target, "x");
        assertTrue(OutputFile.sameFile(target, link), "a link and its existing target");
        Files.createDirectories(dir.resolve("sub"));
        assertTrue(OutputFile.sameFile(dir.resolve("new.png"), dir.resolve("sub/../new.png")), "one path spelt two ways");
        Path hard = Files.createLink(dir.resolve("hard.csv"), target);
        assertTrue(OutputFile.sameFile(hard, target), "two hard links to one file");
        assertFalse(OutputFile.sameFile(dir.resolve("a.png"), dir.resolve("b.png")));
        assertFalse(OutputFile.sameFile(link, dir.resolve("new.png")));
    }

    @Test
    void aDeviceNamedTwiceIsNoClashForNothingIsReplaced() {
        Path devNull = Path.of("/dev/null");
        if (Files.exists(devNull)) {
            assertFalse(OutputFile.sameFile(devNull, devNull));
        }
    }
}
