package sitcov.protocol;

import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import sitcov.control.ControllerFactory;

/**
 * The controllers written in Java that run in sitcov's process, by the name {@code java:NAME} gives
 * them wherever a controller is named (experiments/controllers/README.md, "A controller in Java"). A controller is a
 * class
 * implementing {@link sitcov.control.Controller} and a factory that makes one per run; adding one takes
 * that class and one line, a {@link #register} call made before the command runs (by a test, or by the
 * program that embeds sitcov and calls {@code sitcov.cli.Main.run}).
 */
public final class JavaControllers {
    private static final Map<String, ControllerFactory> REGISTERED = new TreeMap<>();

    private JavaControllers() {
    }

    /**
     * Makes {@code factory}'s controllers the controller {@code java:NAME}.
     *
     * @throws IllegalArgumentException if the name is taken or is not a plain name
     */
    public static synchronized void register(String name, ControllerFactory factory) {
        if (!name.matches("[A-Za-z0-9][A-Za-z0-9._-]*")) {
            throw new IllegalArgumentException("a Java controller's name is letters, digits, '.', '_' and '-', not '"
                    + name + "'");
        }
        if (REGISTERED.putIfAbsent(name, factory) != null && REGISTERED.get(name) != factory) {
            throw new IllegalArgumentException("a Java controller named '" + name + "' is registered already");
        }
    }

    /** The factory registered as {@code name}. */
    public static synchronized Optional<ControllerFactory> named(String name) {
        return Optional.ofNullable(REGISTERED.get(name));
    }

    /** Every registered name, sorted. */
    public static synchronized Set<String> names() {
        return Set.copyOf(REGISTERED.keySet());
    }
}
