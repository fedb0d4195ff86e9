package sitcov.results;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;

/**
 * For tests: a row of a folder's runs.csv changed and checked again as sitcov would have written
 * it, as in a folder judged by another build of sitcov (which the checks cannot tell, but replay can).
 */
public final class SignedEdits {
    private SignedEdits() {
    }

    /** Replaces line {@code line} (1 is the header) by {@code edit} of it, without its check, and checks it again. */
    public static void editRunsRow(Path folder, int line, UnaryOperator<String> edit) throws IOException {
        JournalCheck check = JournalCheck.of(Manifest.read(folder));
        Path runs = folder.resolve(ResultsFolder.RUNS);
        List<String> lines = new ArrayList<>(Files.readAllLines(runs));
        String row = lines.get(line - 1);
        String edited = edit.apply(row.substring(0, row.lastIndexOf(',')));
        lines.set(line - 1, check.rows(edited + "\n").strip());
        Files.write(runs, lines);
    }
}
