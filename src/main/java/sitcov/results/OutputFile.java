package sitcov.results;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Set;

/**
 * One output file being written. A regular file is written beside itself and moved into place
 * whole on {@link #commit()}, so a failure never leaves half a file, and it keeps the mode it had
 * (a new one is readable by others, 0644). A link is followed, and the file it names is replaced,
 * not the link. A device or pipe (such as {@code /dev/null}) is written straight into: a rename would
 * put a regular file in its place.
 */
public final class OutputFile implements AutoCloseable {
    /** Results are for sharing: readable by everyone, as a file made by a shell would be. */
    static final Set<PosixFilePermission> READABLE = PosixFilePermissions.fromString("rw-r--r--");

    private final Path target;
    private final Path temp;
    private final OutputStream stream;
    private boolean committed;

    private OutputFile(Path target, Path temp, OutputStream stream) {
        this.target = target;
        this.temp = temp;
        this.stream = stream;
    }

    /** @throws IOException naming {@code file} and the reason ({@link IoReason#about}) */
    public static OutputFile open(Path file) throws IOException {
        try {
            return start(file);
        } catch (IOException e) {
            throw IoReason.about(file, e);
        }
    }

    private static OutputFile start(Path file) throws IOException {
        Path target = file.toAbsolutePath();
        if (Files.isDirectory(target)) {
            throw new IOException(file + " is a folder; name a file");
        }
        if (Files.exists(target) && !Files.isRegularFile(target)) {
            // a device, a pipe, or a link to one (/dev/stdout): write into it, never rename over it
            return new OutputFile(target, null, Files.newOutputStream(target, StandardOpenOption.WRITE,
                    StandardOpenOption.TRUNCATE_EXISTING));
        }
        if (Files.isSymbolicLink(target)) {
            try {
                target = target.toRealPath();
            } catch (NoSuchFileException e) {
                throw new IOException(file + " is a link to " + Files.readSymbolicLink(target) + ", which does not exist");
            }
        }
        Path temp = Files.createTempFile(target.getParent(), "." + target.getFileName(), ".tmp");
        try {
            if (Files.getFileStore(temp).supportsFileAttributeView("posix")) {
                Files.setPosixFilePermissions(temp, Files.exists(target) ? Files.getPosixFilePermissions(target) : READABLE);
            }
            return new OutputFile(target, temp, Files.newOutputStream(temp));
        } catch (IOException | RuntimeException e) {
            Files.deleteIfExists(temp);
            throw e;
        }
    }

    /**
     * Whether writing {@code a} and writing {@code b} would write one file, so that one output
     * would replace the other: the same path, a link and the file it names (however spelt), or two
     * hard links to one file. A device or pipe is written into, not replaced, so naming it twice
     * ({@code /dev/null}) loses nothing and is not a clash.
     */
    public static boolean sameFile(Path a, Path b) {
        Path ra = identity(a);
        Path rb = identity(b);
        if (!ra.equals(rb)) {
            try {
                return Files.exists(ra) && Files.exists(rb) && Files.isSameFile(ra, rb);
            } catch (IOException e) {
                return false;
            }
        }
        return !Files.exists(ra) || Files.isRegularFile(ra);
    }

    /**
     * The file that writing {@code file} changes: its real path when it exists; for one not yet
     * there, the real path of its folder and its name; for a link to a file not yet there, that file.
     */
    static Path identity(Path file) {
        Path path = file.toAbsolutePath().normalize();
        for (int links = 0; links < 40; links++) { // a loop of links ends somewhere
            try {
                return path.toRealPath();
            } catch (IOException missing) {
                if (!Files.isSymbolicLink(path)) {
                    break;
                }
                try {
                    path = path.resolveSibling(Files.readSymbolicLink(path)).toAbsolutePath().normalize();
                } catch (IOException e) {
                    break;
                }
            }
        }
        Path parent = path.getParent();
        try {
            return parent == null ? path : parent.toRealPath().resolve(path.getFileName());
        } catch (IOException e) {
            return path;
        }
    }

    public OutputStream stream() {
        return stream;
    }

    /** Finishes the file: moves it into place, atomically where the file system can. */
    public void commit() throws IOException {
        try {
            stream.close();
            if (temp != null) {
                try {
                    Files.move(temp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
                } catch (AtomicMoveNotSupportedException e) {
                    Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING);
                }
            }
        } catch (IOException e) {
            throw IoReason.about(target, e);
        }
        committed = true;
    }

    /** Gives up a file not committed: the target is left as it was. */
    @Override
    public void close() throws IOException {
        stream.close();
        if (!committed && temp != null) {
            Files.deleteIfExists(temp);
        }
    }

    /** Writes {@code rows} as UTF-8 lines ending in '\n', whole or not at all. */
    public static void writeLines(Path file, java.util.List<String> rows) throws IOException {
        StringBuilder text = new StringBuilder();
        for (String row : rows) {
            text.append(row).append('\n');
        }
        writeString(file, text.toString());
    }

    /** Writes {@code text} as UTF-8 to {@code file}, whole or not at all. */
    public static void writeString(Path file, String text) throws IOException {
        writeBytes(file, text.getBytes(StandardCharsets.UTF_8));
    }

    /** Writes {@code bytes} to {@code file}, whole or not at all. */
    public static void writeBytes(Path file, byte[] bytes) throws IOException {
        try (OutputFile out = open(file)) {
            try {
                out.stream().write(bytes);
            } catch (IOException e) {
                throw IoReason.about(file, e);
            }
            out.commit();
        }
    }
}
