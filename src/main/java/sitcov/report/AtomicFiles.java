package sitcov.report;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/** Text files of the results, written whole through {@link OutputFile}. */
final class AtomicFiles {
    private AtomicFiles() {
    }

    /** Writes {@code rows} as UTF-8 lines ending in '\n'. */
    static void writeLines(Path file, List<String> rows) throws IOException {
        StringBuilder text = new StringBuilder();
        for (String row : rows) {
            text.append(row).append('\n');
        }
        OutputFile.writeString(file, text.toString());
    }

    static void writeString(Path file, String text) throws IOException {
        OutputFile.writeString(file, text);
    }
}
