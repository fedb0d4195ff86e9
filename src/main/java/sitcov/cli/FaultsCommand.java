package sitcov.cli;

import java.io.PrintStream;
import java.util.List;
import java.util.Set;
import sitcov.builtin.BuiltinCar;
import sitcov.control.ControllerFactory;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.control.ControllerSource;
import sitcov.judge.FaultCalibration;
import sitcov.judge.Variant;
import sitcov.judge.VariantList;
import sitcov.seam.SeamFault;

/**
 * {@code faults}: lists the catalogue; with {@code --calibrate --maps N}, runs every fault of a
 * set on N random maps and prints how often each is reached, effective and found.
 */
final class FaultsCommand implements Command {
    /** The calibration keeps every map's verdicts in memory for its table. */
    static final int MAX_MAPS = 20_000;

    @Override
    public String name() {
        return "faults";
    }

    @Override
    public String synopsis() {
        return "[--calibrate --maps N [--seed S0 (default: 1)] [--faults SET (default: ALL) | --faults seam:ALL|seam:NAME,…"
                + " [--controller C (default: builtin)]] [--threads T] [--fork on|off]]";
    }

    @Override
    public String summary() {
        return "list the seeded faults and the seam faults, or calibrate them: reached, effective and found on N random maps";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--maps", "--seed", "--faults", "--threads", "--fork",
                "--controller"),
                Set.of("--calibrate"));
        options.noPositional();
        if (!options.has("--calibrate")) {
            for (String calibrationOnly : List.of("--maps", "--seed", "--faults", "--threads", "--fork",
                    "--controller")) {
                if (options.has(calibrationOnly)) {
                    throw new UsageException("faults: " + calibrationOnly + " goes with --calibrate; add --calibrate"
                            + " to run the faults, or drop it to list them.");
                }
            }
            list(out);
            return ExitCode.OK;
        }
        int maps = options.count("--maps", 1, MAX_MAPS).orElseThrow(() -> new UsageException(
                "faults: --calibrate needs --maps N, the number of random maps to run each fault on (e.g. 1000)."));
        long first = options.firstSeed("--seed", maps);
        if (options.value("--faults").filter(SeamFault::names).isPresent()) {
            return calibrateSeams(options, first, maps, out, err);
        }
        if (options.has("--controller") && !options.value("--controller").orElseThrow().strip().equals("builtin")) {
            throw new UsageException("faults: the seeded faults act only inside the builtin car; --controller goes with"
                    + " seam faults (--faults seam:ALL), or drop it.");
        }
        Set<Fault> faults = options.faults("--faults").orElse(FaultSet.parse("ALL"));
        if (faults.isEmpty()) {
            throw new UsageException("faults: the fault set is empty; name at least one fault (e.g. --faults PAPER).");
        }
        int threads = options.threads(err);
        Progress progress = new Progress(err, "faults", maps,
                err == System.err && System.console() != null, System::nanoTime);
        ControllerFactory car = options.forks() ? BuiltinCar.FACTORY : BuiltinCar.FACTORY.unforked();
        var results = FaultCalibration.run(first, maps, faults, threads, car, progress::done);
        new FaultCalibrationTable(first, maps, faults, results).print(out);
        return ExitCode.OK;
    }

    /** Every seam fault of {@code --faults} judged on the controller {@code --controller} names (default builtin). */
    private int calibrateSeams(Options options, long first, int maps, PrintStream out, PrintStream err)
            throws UsageException {
        List<Variant> variants;
        try {
            variants = VariantList.parse(String.join(";", SeamFault.parseSet(options.value("--faults").orElseThrow())
                    .stream().map(SeamFault::spec).toList()));
        } catch (IllegalArgumentException e) {
            throw new UsageException("faults: --faults: " + e.getMessage() + ".");
        }
        String spec = Controllers.check(options.value("--controller").orElse("builtin"));
        int threads = options.threads(err);
        Progress progress = new Progress(err, "faults", maps, err == System.err && System.console() != null, System::nanoTime);
        try (ControllerSource opened = Controllers.open(spec, null)) {
            ControllerSource source = options.forks() ? opened : opened.unforked();
            var results = FaultCalibration.runVariants(first, maps, variants, threads, source, progress::done);
            new FaultCalibrationTable(first, maps, variants, spec, results).print(out);
        }
        return ExitCode.OK;
    }

    private static void list(PrintStream out) {
        out.println("The seeded faults of the autonomous car (catalogue: faults/README.md).");
        out.println("Fault sets: PAPER (*), ALL, NONE, ids, ranges such as 8-13, exclusions such as ALL,-0.");
        out.println();
        for (Fault f : Fault.values()) {
            out.printf("%3d %s %-34s %s%n", f.id(), f.paperId().isPresent() ? "*" : " ", f.label(), f.description());
        }
        out.println();
        out.println("The seam faults: sensor and actuator faults of any controller (variants=seam:NAME, seam:ALL;");
        out.println("calibrate with --faults seam:ALL [--controller C]).");
        out.println();
        for (SeamFault f : SeamFault.values()) {
            out.printf("%-28s %s%n", f.spec(), f.description());
        }
    }
}
