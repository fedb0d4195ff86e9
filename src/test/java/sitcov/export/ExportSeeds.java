package sitcov.export;

import java.util.stream.LongStream;

/** The external seeds the export's tests run over: 1..N, N from {@code -Dsitcov.export.seeds=N} (README, issue 29). */
final class ExportSeeds {
    static final String PROPERTY = "sitcov.export.seeds";

    private ExportSeeds() {
    }

    /** Seeds 1..N, N the property's value or {@code fallback}, which keeps the test a few seconds long. */
    static LongStream upTo(int fallback) {
        String given = System.getProperty(PROPERTY);
        int n = given == null || given.isBlank() ? fallback : Integer.parseInt(given.trim());
        return LongStream.rangeClosed(1, n);
    }
}
