package sitcov.results;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import javax.imageio.IIOException;
import org.junit.jupiter.api.Test;

class IoReasonTest {
    @Test
    void aPermissionFailureSaysPermissionDeniedNotJustThePath() {
        // the JDK's AccessDeniedException message is the path alone
        AccessDeniedException denied = new AccessDeniedException("/data/results");
        assertEquals("/data/results", denied.getMessage());
        assertEquals("/data/results: permission denied", IoReason.of(denied));
        assertEquals("permission denied", IoReason.of(denied, Path.of("/data/results")), "the message names it already");
        assertEquals("/data: permission denied", IoReason.of(new AccessDeniedException("/data"), Path.of("/data/results")),
                "a parent that refused is named");
        assertEquals("/x: no such file or folder", IoReason.of(new NoSuchFileException("/x")));
    }

    @Test
    void theOperatingSystemsReasonIsKeptAndAWrappedPngFailureUnwrapped() {
        assertEquals("/mnt/a.csv: no space left on device",
                IoReason.of(new FileSystemException("/mnt/a.csv", null, "No space left on device")));
        IIOException png = new IIOException("I/O error writing PNG file!", new IOException("No space left on device"));
        assertEquals("no space left on device", IoReason.of(png));
    }

    @Test
    void aFailureAboutAFileNamesThatFileAndItsReason() {
        Path file = Path.of("/out/map.png");
        FileSystemException named = IoReason.about(file, new IIOException("I/O error writing PNG file!",
                new IOException("No space left on device")));
        assertEquals("/out/map.png", named.getFile());
        assertEquals("no space left on device", named.getReason());
        assertEquals("no space left on device", IoReason.of(named, file));
        FileSystemException temp = IoReason.about(file, new AccessDeniedException("/out/.map.png123.tmp"));
        assertEquals("/out/map.png: permission denied", IoReason.of(temp), "the target, not the temporary file beside it");
        assertSame(named, IoReason.about(file, named), "named once, not twice");
    }
}
