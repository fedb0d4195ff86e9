package sitcov.report;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * A run's claim on its results folder: an operating-system lock on a file in it, held while the
 * run writes. A second run into the same folder is refused at once; a run that was killed leaves
 * the file but not the lock, so its folder can be resumed.
 */
public final class FolderLock implements AutoCloseable {
    private final Path file;
    private final FileChannel channel;
    private final FileLock lock;

    private FolderLock(Path file, FileChannel channel, FileLock lock) {
        this.file = file;
        this.channel = channel;
        this.lock = lock;
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
            throw new IllegalStateException("another run is writing into " + folder + " (it holds " + file
                    + "); wait for it to end or choose another folder");
        }
        return new FolderLock(file, channel, lock);
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
