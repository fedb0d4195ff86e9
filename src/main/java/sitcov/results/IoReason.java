package sitcov.results;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.IIOException;

/**
 * Why an I/O operation failed, in words a message can end with. The JDK names some failures only by
 * their path (an {@link AccessDeniedException}'s message is the path alone) and ImageIO hides the
 * cause behind "I/O error writing PNG file!"; a user needs the reason, and the file when it is not
 * the one the message already names.
 */
public final class IoReason {
    private IoReason() {
    }

    /** The reason, after the file it happened to: "/data/out: permission denied". */
    public static String of(IOException e) {
        return of(e, null);
    }

    /** The reason alone when it happened to {@code subject}, the file the message names already. */
    public static String of(IOException e, Path subject) {
        if (e instanceof IIOException && e.getCause() instanceof IOException cause) {
            return of(cause, subject);
        }
        if (e instanceof FileSystemException f) {
            String file = f.getFile();
            boolean named = file == null || subject != null
                    && (file.equals(subject.toString()) || file.equals(subject.toAbsolutePath().toString()));
            return named ? reason(f) : file + ": " + reason(f);
        }
        return e.getMessage() == null ? e.getClass().getSimpleName() : lowerFirst(e.getMessage());
    }

    /**
     * The failure of writing or reading {@code file}, as an exception that names it and says why: the
     * JDK's own may name a temporary file beside it, or nothing at all (a full disk).
     */
    public static FileSystemException about(Path file, IOException e) {
        if (e instanceof FileSystemException f && file.toString().equals(f.getFile()) && f.getReason() != null) {
            return f;
        }
        FileSystemException named = new FileSystemException(file.toString(), null, bare(e));
        named.initCause(e);
        return named;
    }

    /** The reason without any file. */
    private static String bare(IOException e) {
        if (e instanceof IIOException && e.getCause() instanceof IOException cause) {
            return bare(cause);
        }
        if (e instanceof FileSystemException f) {
            return reason(f);
        }
        return of(e);
    }

    private static String reason(FileSystemException f) {
        if (f.getReason() != null) {
            return lowerFirst(f.getReason());
        }
        if (f instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (f instanceof NoSuchFileException) {
            return "no such file or folder";
        }
        if (f instanceof FileAlreadyExistsException) {
            return "it exists already";
        }
        if (f instanceof NotDirectoryException) {
            return "not a folder";
        }
        if (f instanceof DirectoryNotEmptyException) {
            return "the folder is not empty";
        }
        return "failed (" + f.getClass().getSimpleName() + ")";
    }

    /** "No space left on device" reads "no space left on device" after a colon; "PNG" stays as it is. */
    private static String lowerFirst(String s) {
        if (s.length() > 1 && Character.isUpperCase(s.charAt(0)) && Character.isLowerCase(s.charAt(1))) {
            return s.substring(0, 1).toLowerCase(Locale.ROOT) + s.substring(1);
        }
        return s;
    }
}
