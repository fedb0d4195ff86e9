package sitcov.results;

import java.util.ArrayList;
import java.util.List;

/** The lines of a journal file that were written whole: a line a kill cut short (no final '\n') is dropped. */
final class CsvLines {
    private CsvLines() {
    }

    static List<String> complete(String text) {
        List<String> lines = new ArrayList<>();
        int start = 0;
        for (int nl = text.indexOf('\n'); nl >= 0; nl = text.indexOf('\n', start)) {
            lines.add(text.substring(start, nl));
            start = nl + 1;
        }
        return lines;
    }
}
