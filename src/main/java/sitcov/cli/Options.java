package sitcov.cli;

import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.results.OutputFile;

/**
 * The options of one command: {@code --name value} (or {@code --name=value}) for valued options,
 * {@code --name} for flags, anything else positional. Every mistake becomes a {@link UsageException}
 * that names the command and the fix.
 */
final class Options {
    /** Far more threads than any machine sitcov runs on has cores. */
    static final int MAX_THREADS = 4096;

    private final String command;
    private final Map<String, String> values = new LinkedHashMap<>();
    private final Set<String> flags = new LinkedHashSet<>();
    private final List<String> positional = new ArrayList<>();
    /** The files asked for so far, by option: none may be written twice, nor written over while read. */
    private final Map<String, Path> outputs = new LinkedHashMap<>();
    private final Map<String, Path> inputs = new LinkedHashMap<>();

    private Options(String command) {
        this.command = command;
    }

    static Options parse(String command, List<String> args, Set<String> valued, Set<String> flagNames)
            throws UsageException {
        Options options = new Options(command);
        for (int i = 0; i < args.size(); i++) {
            String arg = args.get(i);
            if (!arg.startsWith("--")) {
                options.positional.add(arg);
                continue;
            }
            int eq = arg.indexOf('=');
            String name = eq < 0 ? arg : arg.substring(0, eq);
            if (valued.contains(name)) {
                String value;
                if (eq >= 0) {
                    value = arg.substring(eq + 1);
                } else if (i + 1 < args.size() && !args.get(i + 1).startsWith("--")) {
                    value = args.get(++i);
                } else {
                    throw new UsageException(command + ": " + name + " needs a value.");
                }
                if (options.values.put(name, value) != null) {
                    throw new UsageException(command + ": " + name + " is given twice; give it once.");
                }
            } else if (flagNames.contains(name) && eq < 0) {
                options.flags.add(name);
            } else {
                Set<String> all = new java.util.TreeSet<>(valued);
                all.addAll(flagNames);
                throw new UsageException(command + ": unknown option '" + arg + "'; the options are "
                        + String.join(", ", all) + ".");
            }
        }
        return options;
    }

    boolean has(String name) {
        return flags.contains(name) || values.containsKey(name);
    }

    Optional<String> value(String name) {
        return Optional.ofNullable(values.get(name));
    }

    List<String> positional() {
        return positional;
    }

    void noPositional() throws UsageException {
        if (!positional.isEmpty()) {
            throw new UsageException(command + ": unexpected argument '" + positional.get(0) + "'.");
        }
    }

    /** A seed: any whole number that fits in 64 bits. */
    Optional<Long> seed(String name) throws UsageException {
        Optional<String> text = value(name);
        if (text.isEmpty()) {
            return Optional.empty();
        }
        try {
            return Optional.of(Long.parseLong(text.get().strip()));
        } catch (NumberFormatException e) {
            throw new UsageException(command + ": " + name + " needs a whole number such as 42 (64-bit), not '"
                    + text.get() + "'.");
        }
    }

    /**
     * The first of {@code maps} consecutive seeds, from {@code name} (default 1); refused when the
     * range would run past the largest seed.
     */
    long firstSeed(String name, int maps) throws UsageException {
        long first = seed(name).orElse(1L);
        if (first > Long.MAX_VALUE - (maps - 1)) {
            throw new UsageException(command + ": seeds " + first + " + " + maps + " maps run past the largest seed;"
                    + " choose a smaller " + name + ".");
        }
        return first;
    }

    /** A fault set such as PAPER, ALL,-0 or 8-13. */
    Optional<Set<Fault>> faults(String name) throws UsageException {
        Optional<String> text = value(name);
        if (text.isEmpty()) {
            return Optional.empty();
        }
        try {
            return Optional.of(FaultSet.parse(text.get()));
        } catch (IllegalArgumentException e) {
            throw new UsageException(command + ": " + name + ": " + e.getMessage() + ".");
        }
    }

    /** A count from {@code min} to {@code max}; the limit is named when it is passed. */
    Optional<Integer> count(String name, int min, int max) throws UsageException {
        Optional<String> text = value(name);
        if (text.isEmpty()) {
            return Optional.empty();
        }
        try {
            long v = Long.parseLong(text.get().strip());
            if (v >= min && v <= max) {
                return Optional.of((int) v);
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new UsageException(command + ": " + name + " needs a whole number from " + min + " to " + max + ", not '"
                + text.get() + "'.");
    }

    /** Worker threads: at least one; more than the machine's cores are capped, and said so on {@code err}. */
    int threads(java.io.PrintStream err) throws UsageException {
        int cores = Runtime.getRuntime().availableProcessors();
        int asked = count("--threads", 1, MAX_THREADS).orElse(cores);
        if (asked > cores) {
            err.println(command + ": --threads " + asked + " is more than the " + cores + " cores here; using " + cores + ".");
            return cores;
        }
        return asked;
    }

    /**
     * Whether faulty runs are forked from the fault-free run ({@code --fork on}, the default) or run
     * whole ({@code --fork off}, to check that both give the same bytes). Only the speed differs.
     */
    boolean forks() throws UsageException {
        Optional<String> fork = value("--fork");
        if (fork.isEmpty() || fork.get().equals("on")) {
            return true;
        }
        if (fork.get().equals("off")) {
            return false;
        }
        throw new UsageException(command + ": --fork takes on or off, not '" + fork.get() + "'.");
    }

    /**
     * Whether a results folder keeps the recordings of every run ({@code --record all}) or, the default, of
     * its failures and findings only ({@code --record failures}).
     */
    boolean recordsAll() throws UsageException {
        Optional<String> record = value("--record");
        if (record.isEmpty() || record.get().equals("failures")) {
            return false;
        }
        if (record.get().equals("all")) {
            return true;
        }
        throw new UsageException(command + ": --record takes failures (the default: failing runs and findings) or all"
                + " (every run, passing ones too), not '" + record.get() + "'.");
    }

    /** A file to read: it must exist and be a readable file. */
    Optional<Path> inputFile(String name) throws UsageException {
        Optional<Path> path = path(name);
        if (path.isPresent()) {
            Path p = path.get();
            if (!Files.isRegularFile(p) || !Files.isReadable(p)) {
                throw new UsageException(command + ": cannot read " + name + " " + shown(p)
                        + (Files.exists(p) ? " (not a readable file)" : " (no such file)") + "; check the path.");
            }
            for (Map.Entry<String, Path> output : outputs.entrySet()) {
                if (OutputFile.sameFile(output.getValue(), p)) {
                    throw new UsageException(command + ": " + name + " " + shown(p) + " and " + output.getKey() + " "
                            + shown(output.getValue()) + " are the same file; write " + output.getKey()
                            + " elsewhere, or it would replace what is read.");
                }
            }
            inputs.put(name, p);
        }
        return path;
    }

    /**
     * A file to write: its folder must exist and be writable; the file itself may be replaced. It
     * may not be the file of another output of the same command (see {@link OutputFile#sameFile}):
     * each output is checked here, against those asked for before it, so every command with
     * several outputs refuses a clash before it writes anything.
     */
    Optional<Path> outputFile(String name) throws UsageException {
        Optional<Path> path = path(name);
        if (path.isPresent()) {
            checked(name, path.get());
        }
        return path;
    }

    /** {@link #outputFile(String)}, or {@code otherwise} when {@code name} is not given: a default output is checked too. */
    Path outputFile(String name, Path otherwise) throws UsageException {
        Optional<Path> path = outputFile(name);
        if (path.isPresent()) {
            return path.get();
        }
        checked(name + " (by default " + shown(otherwise) + ")", otherwise);
        return otherwise;
    }

    private void checked(String name, Path file) throws UsageException {
        Path p = file.toAbsolutePath();
        Path folder = p.getParent();
        if (Files.isDirectory(p)) {
            throw new UsageException(command + ": " + name + " " + shown(file) + " is a folder; name a file in it.");
        }
        if (folder == null || !Files.isDirectory(folder)) {
            throw new UsageException(command + ": the folder of " + name + " " + shown(file)
                    + " does not exist; create it first.");
        }
        if (!Files.isWritable(folder)) {
            throw new UsageException(command + ": cannot write into " + folder + " for " + name
                    + "; choose a writable folder.");
        }
        clash(name, file, outputs, "give each its own file");
        clash(name, file, inputs, "write " + name + " elsewhere, or it would replace what is read");
        outputs.put(name, file);
    }

    /** Refuses {@code file} for option {@code name} if it is the file of one of {@code earlier}. */
    private void clash(String name, Path file, Map<String, Path> earlier, String fix) throws UsageException {
        for (Map.Entry<String, Path> e : earlier.entrySet()) {
            if (OutputFile.sameFile(e.getValue(), file)) {
                throw new UsageException(command + ": " + (e.getValue().equals(file)
                        ? e.getKey() + " and " + name + " both name " + shown(file)
                        : e.getKey() + " " + shown(e.getValue()) + " and " + name + " " + shown(file) + " are the same file")
                        + "; " + fix + ".");
            }
        }
    }

    /** A path as messages show it: an empty one as '' rather than nothing. */
    static String shown(Path p) {
        return p.toString().isEmpty() ? "''" : p.toString();
    }

    private Optional<Path> path(String name) throws UsageException {
        Optional<String> text = value(name);
        if (text.isEmpty()) {
            return Optional.empty();
        }
        try {
            return Optional.of(Path.of(text.get()));
        } catch (InvalidPathException e) {
            throw new UsageException(command + ": " + name + " '" + text.get() + "' is not a valid path.");
        }
    }
}
