/**
 * Controllers as programs speaking JSON Lines over stdin and stdout, in lockstep (experiments/controllers/README.md,
 * "Testing your own controller", "The protocol"). sitcov's side: {@link sitcov.protocol.ExecControllers} starts a
 * program per worker thread, under a watchdog shell, and its {@link sitcov.protocol.ProxyFactory}
 * hands the world a controller that sends observations and reads commands within the per-tick
 * timeout. The controller's side: {@link sitcov.protocol.ControllerServer} serves any
 * {@link sitcov.control.ControllerFactory} (the builtin car, for {@code sitcov controller builtin}),
 * handing a seeded one the run's faults the reset names and sending back what they did. The
 * registry: {@link sitcov.protocol.ControllerChoice} reads {@code builtin}, {@code builtin:FAULTS},
 * {@code java:NAME} ({@link sitcov.protocol.JavaControllers}) or {@code exec:COMMAND}; with the
 * command line, it is the only package that names the builtin car. The JSON
 * reader and writer are its own (JDK only); doubles cross the pipe bit for bit.
 */
package sitcov.protocol;
