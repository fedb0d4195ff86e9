package sitcov.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Properties;

/** The version Maven wrote into {@code sitcov/version.properties} at build time. */
final class Version {
    private static final String UNKNOWN = "unknown";

    private Version() {
    }

    static String current() {
        try (InputStream in = Version.class.getResourceAsStream("/sitcov/version.properties")) {
            if (in == null) {
                return UNKNOWN;
            }
            Properties properties = new Properties();
            properties.load(in);
            String version = properties.getProperty("version", UNKNOWN);
            return version.startsWith("${") ? UNKNOWN : version;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read sitcov's version resource", e);
        }
    }
}
