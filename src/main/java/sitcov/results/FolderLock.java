package sitcov.results;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * A run's claim on its results folder: an operating-system lock on a file in it, held while the
 * run writes. A second run into the same folder is refused at once; a run that was killed leaves
 * the file but not the lock, so its folder can be resumed.
 */
public final class FolderLock implements AutoCloseable {
    private final Path folder;
    private final Path file;
    private final FileChannel channel;
    private final FileLock lock;
    /** The lock file's identity (device and inode), to tell it from a new file of the same name. */
    private final Object key;

    private FolderLock(Path folder, Path file, FileChannel channel, FileLock lock, Object key) {
        this.folder = folder;
        this.file = file;
        this.channel = channel;
        this.lock = lock;
        this.key = key;
    }

    /** The folder was deleted, or its lock file removed or replaced, while a command wrote into it. */
    public static final class Lost extends UncheckedIOException {
        private static final long serialVersionUID = 1L;

        Lost(Path folder, IOException cause) {
            super("the results folder " + folder + " was deleted (or its " + ResultsFolder.LOCK + " removed) while this"
                    + " command wrote into it", cause);
        }
    }

    /**
     * Claims {@code folder}, which must exist.
     *
     * @throws IllegalStateException when another run holds it
     */
    public static FolderLock claim(Path folder) throws IOException {
        Path file = folder.resolve(ResultsFolder.LOCK);
        FileChannel channel = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
        FileLock lock;
        try {
            lock = channel.tryLock();
        } catch (OverlappingFileLockException e) {
            lock = null;
        }
        if (lock == null) {
            channel.close();
            throw new IllegalStateException("another run or merge is writing into " + folder + " (it holds " + file
                    + "); wait for it to end or choose another folder");
        }
        return new FolderLock(folder, file, channel, lock, fileKey(file));
    }

    private static Object fileKey(Path file) throws IOException {
        return Files.readAttributes(file, BasicFileAttributes.class).fileKey();
    }

    /**
     * Checks that the claim still stands: the folder and this lock file are where they were. Writes
     * into a deleted folder would succeed unseen (open files outlive their names), and be lost.
     *
     * @throws Lost when they are not
     */
    public void verify() {
        Object now;
        try {
            now = fileKey(file);
        } catch (IOException e) {
            throw new Lost(folder, e);
        }
        if (key != null && !key.equals(now)) {
            throw new Lost(folder, new IOException(file + " is another file now"));
        }
    }

    /** Releases the claim and removes the lock file. */
    @Override
    public void close() throws IOException {
        if (channel.isOpen()) {
            Files.deleteIfExists(file);
            lock.release();
            channel.close();
        }
    }
}
