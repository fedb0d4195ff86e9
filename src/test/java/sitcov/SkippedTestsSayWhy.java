package sitcov;

import java.util.Optional;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.TestWatcher;

/**
 * Says on the console why a test was skipped: Surefire's summary counts skipped tests but does not print the
 * assumption that skipped them (the ASAM schemas or Python's jsonschema not fetched, no python3). Registered for
 * every test class through {@code META-INF/services} and {@code junit-platform.properties}.
 */
public final class SkippedTestsSayWhy implements TestWatcher {

    @Override
    public void testAborted(ExtensionContext context, Throwable cause) {
        say(context, cause == null ? "an assumption did not hold" : cause.getMessage().replaceFirst("^Assumption failed: ", ""));
    }

    @Override
    public void testDisabled(ExtensionContext context, Optional<String> reason) {
        say(context, reason.orElse("disabled"));
    }

    private static void say(ExtensionContext context, String reason) {
        String test = context.getRequiredTestClass().getSimpleName() + "." + context.getDisplayName();
        System.err.println("[sitcov] skipped " + test + ": " + reason);
    }
}
