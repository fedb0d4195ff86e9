package sitcov.protocol;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import sitcov.builtin.BuiltinCar;
import sitcov.control.ControllerFactory;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;

/**
 * Which controller drives the car under test, as a preset or the command line names it:
 * {@code builtin} (sitcov's own car, in process), {@code builtin:FAULTS} (with faults planted),
 * {@code java:NAME} (a Java controller registered in {@link JavaControllers}, in process) or
 * {@code exec:COMMAND ARGS...} (a program that
 * speaks the protocol; the command line is split at spaces, and '...' or "..." keep spaces in one
 * argument).
 */
public sealed interface ControllerChoice {
    /** The choice as written, e.g. {@code exec:python3 lane_follower.py}. */
    String text();

    /**
     * Opens the controllers of one command: in process for the builtin, processes started on
     * demand for a program. Close it when the command is done.
     */
    Workers open(String sitcovVersion, long tickTimeoutMillis, long handshakeTimeoutMillis);

    /** The builtin car. */
    record Builtin() implements ControllerChoice {
        @Override
        public String text() {
            return "builtin";
        }

        @Override
        public Workers open(String sitcovVersion, long tickTimeoutMillis, long handshakeTimeoutMillis) {
            return inProcess(BuiltinCar.FACTORY, text());
        }
    }

    /** The builtin car with {@code faults} always on: a version of it with planted bugs. */
    record Planted(Set<Fault> faults) implements ControllerChoice {
        public Planted {
            faults = Set.copyOf(faults);
        }

        @Override
        public String text() {
            return "builtin:" + FaultSet.format(faults);
        }

        @Override
        public Workers open(String sitcovVersion, long tickTimeoutMillis, long handshakeTimeoutMillis) {
            return inProcess(BuiltinCar.withPlanted(faults), text());
        }
    }

    /** A controller written in Java, registered by name in {@link JavaControllers}, run in process. */
    record InJava(String name) implements ControllerChoice {
        @Override
        public String text() {
            return "java:" + name;
        }

        @Override
        public Workers open(String sitcovVersion, long tickTimeoutMillis, long handshakeTimeoutMillis) {
            return inProcess(JavaControllers.named(name).orElseThrow(), text());
        }
    }

    /** A program speaking the protocol, started by {@code command}. */
    record Exec(List<String> command) implements ControllerChoice {
        public Exec {
            command = List.copyOf(command);
        }

        @Override
        public String text() {
            return "exec:" + String.join(" ", command);
        }

        @Override
        public Workers open(String sitcovVersion, long tickTimeoutMillis, long handshakeTimeoutMillis) {
            ExecControllers controllers = new ExecControllers(command, sitcovVersion, tickTimeoutMillis,
                    handshakeTimeoutMillis);
            return new Workers() {
                @Override
                public ControllerFactory worker(Path log) {
                    return controllers.worker(log);
                }

                @Override
                public String check(Path log) throws ControllerStartException {
                    return controllers.check(log);
                }

                @Override
                public BatchingProxy batched(Path log, int maxBatch) throws ControllerStartException {
                    return controllers.batched(log, maxBatch);
                }

                @Override
                public void close() {
                    controllers.close();
                }
            };
        }
    }

    /** Controllers that run in sitcov's process: one factory for every thread, no program to start or end. */
    private static Workers inProcess(ControllerFactory factory, String name) {
        return new Workers() {
            @Override
            public ControllerFactory worker(Path log) {
                return factory;
            }

            @Override
            public String check(Path log) {
                return name;
            }

            @Override
            public void close() {
            }
        };
    }

    /** The controllers of one command: a factory per worker thread. */
    interface Workers extends AutoCloseable {
        /** The factory of one worker thread; a program's stderr goes to {@code log} (discarded when null). */
        ControllerFactory worker(Path log);

        /** Starts the controller once and handshakes, before anything runs: its name and version. */
        String check(Path log) throws ControllerStartException;

        /**
         * One controller process stepping up to {@code maxBatch} runs together (batched lockstep);
         * null for a controller that is not a program.
         */
        default BatchingProxy batched(Path log, int maxBatch) throws ControllerStartException {
            return null;
        }

        @Override
        void close();
    }

    /**
     * Reads {@code builtin} or {@code exec:COMMAND ARGS...}.
     *
     * @throws IllegalArgumentException saying what is accepted
     */
    static ControllerChoice parse(String text) {
        String t = text.strip();
        if (t.equals("builtin")) {
            return new Builtin();
        }
        if (t.startsWith("builtin:")) {
            Set<Fault> faults = FaultSet.parse(t.substring("builtin:".length()));
            if (faults.isEmpty()) {
                throw new IllegalArgumentException("builtin: needs the faults to plant, e.g. builtin:16 or builtin:16,17");
            }
            return new Planted(faults);
        }
        if (t.startsWith("java:")) {
            String name = t.substring("java:".length()).strip();
            if (JavaControllers.named(name).isEmpty()) {
                throw new IllegalArgumentException("java:" + name + " is not a registered Java controller; "
                        + (JavaControllers.names().isEmpty() ? "none is registered"
                        : "the registered ones are " + String.join(", ", JavaControllers.names())));
            }
            return new InJava(name);
        }
        if (t.startsWith("exec:")) {
            List<String> words = split(t.substring("exec:".length()));
            if (words.isEmpty()) {
                throw new IllegalArgumentException("exec: needs a command, e.g. exec:python3 experiments/controllers/"
                        + "lane_follower.py");
            }
            return new Exec(words);
        }
        throw new IllegalArgumentException("a controller is builtin, builtin:FAULTS (the builtin car with those faults"
                + " always on, e.g. builtin:16), java:NAME (a registered Java controller) or exec:COMMAND ARGS (e.g."
                + " exec:python3 experiments/controllers/lane_follower.py), not '" + text + "'");
    }

    /** Splits at white space; '...' and "..." keep their spaces. */
    private static List<String> split(String line) {
        List<String> words = new ArrayList<>();
        StringBuilder word = new StringBuilder();
        boolean inWord = false;
        char quote = 0;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (quote != 0) {
                if (c == quote) {
                    quote = 0;
                } else {
                    word.append(c);
                }
            } else if (c == '\'' || c == '"') {
                quote = c;
                inWord = true;
            } else if (Character.isWhitespace(c)) {
                if (inWord) {
                    words.add(word.toString());
                    word.setLength(0);
                    inWord = false;
                }
            } else {
                word.append(c);
                inWord = true;
            }
        }
        if (quote != 0) {
            throw new IllegalArgumentException("exec: a quote is not closed in '" + line + "'");
        }
        if (inWord) {
            words.add(word.toString());
        }
        return words;
    }
}
