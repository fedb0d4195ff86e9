package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import sitcov.results.ResultsFolder;

/** Prints the verdict a finished comparison kept in its results folder (a sweep has none). */
final class VerdictPrinter {
    private VerdictPrinter() {
    }

    static void print(PrintStream out, Path folder) {
        Path verdict = folder.resolve(ResultsFolder.VERDICT);
        if (!Files.isRegularFile(verdict)) {
            return;
        }
        try {
            out.println();
            out.println("Verdict (kept in " + verdict + "):");
            Files.readAllLines(verdict).forEach(out::println);
            out.println();
        } catch (IOException e) {
            out.println("(the verdict in " + verdict + " could not be read: " + e.getMessage() + ")");
        }
    }
}
