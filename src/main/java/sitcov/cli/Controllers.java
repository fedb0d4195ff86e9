package sitcov.cli;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import sitcov.control.ControllerFactory;
import sitcov.control.ControllerSource;
import sitcov.experiment.ExperimentConfig;
import sitcov.faults.FaultSet;
import sitcov.judge.Variant;
import sitcov.protocol.ControllerChoice;
import sitcov.protocol.ControllerStartException;
import sitcov.protocol.ExecControllers;

/**
 * The controller a preset, {@code --controller} or {@code versions} names — {@code builtin},
 * {@code builtin:FAULTS} or {@code exec:COMMAND ARGS…} (experiments/controllers/README.md, "Testing your own
 * controller") — made
 * ready for an experiment's worker threads: a program is started and handshaken once before
 * anything runs, then each worker thread gets a process of its own, its stderr in
 * {@code controller-N.log} of the results folder.
 */
final class Controllers {
    /** How the builtin car served over the protocol ({@code controller builtin}) names itself in its hello. */
    private static final String BUILTIN_SERVED = "sitcov-builtin";

    private Controllers() {
    }

    /** The spec as given, once it names a controller sitcov can start. */
    static String check(String spec) throws UsageException {
        try {
            ControllerChoice.parse(spec);
            return spec.strip();
        } catch (IllegalArgumentException e) {
            throw new UsageException("controller: " + e.getMessage() + ".");
        }
    }

    /** Starts what {@code spec} names, handshaking a program at once; its logs go into {@code folder} (null: kept nowhere). */
    static ControllerSource open(String spec, Path folder) throws UsageException {
        return open(spec, folder, "controller");
    }

    /** As {@link #open(String, Path)}, its logs named {@code LOGS-N.log}: several controllers share one folder. */
    static ControllerSource open(String spec, Path folder, String logs) throws UsageException {
        return start(spec, folder, logs).source();
    }

    /** The controllers of an experiment, each started and handshaken: the reference's and each variant's of its own. */
    record Opened(ControllerSource reference, Map<Integer, ControllerSource> variants) implements AutoCloseable {
        /** The same, with the reference's runs run whole ({@code --fork off}): variants of their own run whole anyway. */
        Opened unforked() {
            return new Opened(reference.unforked(), variants);
        }

        @Override
        public void close() {
            reference.close();
            variants.values().forEach(ControllerSource::close);
        }
    }

    /**
     * Starts the experiment's reference and every variant that is a controller of its own (logs in
     * {@code controller-N.log} and {@code controller-variant-ID-N.log}). Seeded faults of the builtin car
     * are variants only of the builtin car (in process, with faults planted or not, or served over the
     * protocol by {@code controller builtin}): for any other reference they could not act, so they are
     * refused before anything runs.
     */
    static Opened open(ExperimentConfig config, Path folder) throws UsageException {
        Started reference = start(config.controller(), folder, "controller");
        Map<Integer, ControllerSource> variants = new LinkedHashMap<>();
        try {
            if (!config.faults().isEmpty() && !config.controller().startsWith(ExperimentConfig.BUILTIN)
                    && !reference.hello().startsWith(BUILTIN_SERVED)) {
                throw new UsageException("run: the variants " + FaultSet.format(config.faults()) + " are seeded faults of"
                        + " the builtin car, which " + config.controller() + " does not have: they could not act. Name"
                        + " this controller's own variants (variants=exec:…;java:…, or --variants), or variants=none to"
                        + " seek its own failures; a preset's faults= is the builtin car's shorthand.");
            }
            for (Variant v : config.variants()) {
                if (v instanceof Variant.Controller c) {
                    variants.put(c.id(), start(c.spec(), folder, "controller-variant-" + c.id()).source());
                }
            }
        } catch (UsageException | RuntimeException e) {
            reference.source().close();
            variants.values().forEach(ControllerSource::close);
            throw e;
        }
        return new Opened(reference.source(), variants);
    }

    /** A controller started and handshaken, and what it called itself. */
    private record Started(ControllerSource source, String hello) {
    }

    private static Started start(String spec, Path folder, String logs) throws UsageException {
        ControllerChoice choice;
        try {
            choice = ControllerChoice.parse(spec);
        } catch (IllegalArgumentException e) {
            throw new UsageException("controller: " + e.getMessage() + ".");
        }
        ControllerChoice.Workers workers = choice.open(Version.current(), ExecControllers.DEFAULT_TICK_TIMEOUT_MILLIS,
                ExecControllers.DEFAULT_HANDSHAKE_TIMEOUT_MILLIS);
        String hello;
        try {
            hello = workers.check(null);
        } catch (ControllerStartException e) {
            workers.close();
            throw new UsageException(e.getMessage() + "; fix the controller's command (controller= or --controller).");
        }
        AtomicInteger threads = new AtomicInteger();
        ThreadLocal<ControllerFactory> perThread = ThreadLocal.withInitial(() -> workers.worker(
                choice instanceof ControllerChoice.Exec && folder != null ? folder.resolve(logs + "-" + threads.incrementAndGet() + ".log")
                        : null));
        return new Started(new ControllerSource() {
            @Override
            public ControllerFactory forThisThread() {
                return perThread.get();
            }

            @Override
            public String spec() {
                return choice.text();
            }

            @Override
            public void close() {
                workers.close();
            }
        }, hello);
    }
}
