package sitcov.results;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;

/**
 * For tests: a folder's runs.csv changed and checked again as sitcov would have written it, as in a
 * folder judged by another build of sitcov (which the checks cannot tell, but replay can).
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

    /**
     * Takes the near-miss and robustness columns off runs.csv, header and rows, and checks each row again:
     * the file as a build written before margins were kept wrote it.
     */
    public static void withoutMargins(Path folder) throws IOException {
        JournalCheck check = JournalCheck.of(Manifest.read(folder));
        Path runs = folder.resolve(ResultsFolder.RUNS);
        List<String> lines = Files.readAllLines(runs);
        List<String> header = List.of(lines.get(0).split(",", -1));
        List<Integer> kept = new ArrayList<>();
        for (int i = 0; i < header.size(); i++) {
            if (!header.get(i).startsWith("near_") && !header.get(i).startsWith("rho_")) {
                kept.add(i);
            }
        }
        List<String> out = new ArrayList<>();
        for (int n = 0; n < lines.size(); n++) {
            String[] cells = lines.get(n).split(",", -1);
            List<String> row = new ArrayList<>();
            // a row is checked without its check, the last column; the header is not checked
            int end = n == 0 ? kept.size() : kept.size() - 1;
            for (int k = 0; k < end; k++) {
                row.add(cells[kept.get(k)]);
            }
            out.add(n == 0 ? String.join(",", row) : check.rows(String.join(",", row) + "\n").strip());
        }
        Files.write(runs, out);
    }
}
