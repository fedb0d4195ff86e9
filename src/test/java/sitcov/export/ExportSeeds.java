package sitcov.export;

import java.util.stream.LongStream;

/**
 * The external seeds the export's tests run over: maps 1..N, N from {@code -Dsitcov.export.seeds=N}, and runs
 * recorded on maps 1..R, R from {@code -Dsitcov.export.runs=R} (src/main/java/sitcov/export/README.md, "Export to
 * OpenDRIVE and OpenSCENARIO").
 */
final class ExportSeeds {
    static final String PROPERTY = "sitcov.export.seeds";
    static final String RUNS_PROPERTY = "sitcov.export.runs";

    private ExportSeeds() {
    }

    /** Seeds 1..N, N the property's value or {@code fallback}, which keeps the test a few seconds long. */
    static LongStream upTo(int fallback) {
        return LongStream.rangeClosed(1, count(PROPERTY, fallback));
    }

    /** Maps 1..R whose recorded runs are checked, R the property's value or {@code fallback} (a run costs far more than a map). */
    static LongStream runs(int fallback) {
        return LongStream.rangeClosed(1, count(RUNS_PROPERTY, fallback));
    }

    private static int count(String property, int fallback) {
        String given = System.getProperty(property);
        return given == null || given.isBlank() ? fallback : Integer.parseInt(given.trim());
    }
}
