package sitcov.results;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/** A CSV file of a results folder read back by column name, so the report shows exactly what the file holds. */
public record CsvTable(List<String> header, List<List<String>> rows) {
    public static CsvTable read(Path file) throws IOException {
        if (!Files.isRegularFile(file)) {
            return new CsvTable(List.of(), List.of());
        }
        List<String> lines = Files.readAllLines(file);
        if (lines.isEmpty()) {
            return new CsvTable(List.of(), List.of());
        }
        List<List<String>> rows = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            rows.add(List.of(line.split(",", -1)));
        }
        return new CsvTable(List.of(lines.get(0).split(",", -1)), rows);
    }

    public boolean isEmpty() {
        return rows.isEmpty();
    }

    /**
     * The value of {@code column} in {@code row}. A column the file's header lacks is a reader out of
     * step with the table's writer (the report reads files it has just written), so it fails loudly
     * rather than showing an empty cell.
     */
    public String get(List<String> row, String column) {
        int i = header.indexOf(column);
        if (i < 0) {
            throw new IllegalStateException("the table has no column '" + column + "' (its header: " + header + ")");
        }
        return i >= row.size() ? "" : row.get(i);
    }
}
