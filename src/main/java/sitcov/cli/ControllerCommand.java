package sitcov.cli;

import java.io.FileDescriptor;
import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.util.List;
import java.util.Set;
import sitcov.builtin.BuiltinCar;
import sitcov.faults.Fault;
import sitcov.protocol.ControllerServer;
import sitcov.protocol.ProtocolException;

/**
 * {@code controller builtin [--faults F] [--protocol 1|2]}: the builtin car served over the protocol
 * on stdin and stdout, as an external program would be (experiments/controllers/README.md, "Testing your own
 * controller"); it
 * answers with protocol 2 unless told to speak the deprecated protocol 1. With
 * {@code --controller "exec:java -cp target/classes sitcov.cli.Main controller builtin"} a run gives
 * what the builtin gives in process.
 */
final class ControllerCommand implements Command {
    private final InputStream in;
    private final OutputStream out;

    ControllerCommand() {
        // the raw descriptors: the protocol flushes each message itself
        this(new FileInputStream(FileDescriptor.in), new FileOutputStream(FileDescriptor.out));
    }

    ControllerCommand(InputStream in, OutputStream out) {
        this.in = in;
        this.out = out;
    }

    @Override
    public String name() {
        return "controller";
    }

    @Override
    public String synopsis() {
        return "builtin [--faults SET] [--protocol 1|2 (default: 2)]";
    }

    @Override
    public String summary() {
        return "serve the builtin car over the controller protocol on stdin/stdout (JSON Lines), with the faults"
                + " each reset names plus --faults";
    }

    @Override
    public int run(List<String> args, PrintStream ignored, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--faults", "--protocol"), Set.of());
        if (options.positional().size() != 1 || !options.positional().get(0).equals("builtin")) {
            throw new UsageException("controller: say which controller to serve: 'controller builtin'"
                    + " (the only one sitcov has).");
        }
        Set<Fault> faults = options.faults("--faults").orElse(Set.of());
        int protocol = options.count("--protocol", 1, 2).orElse(2);
        ControllerServer server = new ControllerServer(BuiltinCar.FACTORY, "sitcov-builtin", Version.current(), faults,
                protocol);
        try {
            server.serve(in, out);
        } catch (ProtocolException e) {
            err.println("sitcov: controller: sitcov's message broke the protocol: " + e.getMessage());
            return ExitCode.FAILURE;
        } catch (IOException e) {
            err.println("sitcov: controller: the connection broke: " + e.getMessage());
            return ExitCode.FAILURE;
        }
        return ExitCode.OK;
    }
}
