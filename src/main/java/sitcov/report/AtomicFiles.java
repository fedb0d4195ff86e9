package sitcov.report;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Set;

/** Report files are written beside their target and moved into place whole, so a failure never leaves half a file. */
final class AtomicFiles {
    /** Results are for sharing: readable by everyone, as a file made by a shell would be. */
    static final Set<PosixFilePermission> READABLE = PosixFilePermissions.fromString("rw-r--r--");

    private AtomicFiles() {
    }

    /** Writes {@code rows} as UTF-8 lines ending in '\n' to a temporary file beside {@code file}, then moves it into place. */
    static void writeLines(Path file, List<String> rows) throws IOException {
        StringBuilder text = new StringBuilder();
        for (String row : rows) {
            text.append(row).append('\n');
        }
        writeString(file, text.toString());
    }

    static void writeString(Path file, String text) throws IOException {
        Path temp = temporary(file);
        try {
            try (Writer w = Files.newBufferedWriter(temp, StandardCharsets.UTF_8)) {
                w.write(text);
            }
            moveIntoPlace(temp, file.toAbsolutePath());
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /** An empty temporary file beside {@code file}, readable by others like the file it will become. */
    static Path temporary(Path file) throws IOException {
        Path target = file.toAbsolutePath();
        Path temp = Files.createTempFile(target.getParent(), "." + target.getFileName(), ".tmp");
        if (Files.getFileStore(temp).supportsFileAttributeView("posix")) {
            Files.setPosixFilePermissions(temp, READABLE);
        }
        return temp;
    }

    /** Moves the finished temporary file over {@code target}, atomically where the file system can. */
    static void moveIntoPlace(Path temp, Path target) throws IOException {
        try {
            Files.move(temp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING);
        }
    }
}
