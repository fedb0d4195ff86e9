package sitcov.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.builtin.BuiltinCar;
import sitcov.control.Channel;
import sitcov.control.Command;
import sitcov.control.Controller;
import sitcov.control.RunEnd;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;
import sitcov.judge.RunObserver;
import sitcov.judge.Simulator;
import sitcov.world.MapGenerator;

/**
 * The schema (experiments/controllers/protocol.schema.json) is the contract: every message sitcov
 * writes (its hello, a reset, observations with every sensor and channel, an end), and every
 * message the builtin car's server and the Python examples write, is valid against its definition
 * and the schema as a whole, and sitcov reads those commands; every command on a table of bad ones
 * is refused by sitcov and by the schema alike. The validator is Python's jsonschema, which
 * .ci/fetch-jsonschema installs into target/jsonschema (CI runs it before the tests); without
 * python3 and jsonschema the test is skipped with a message, except under CI=true, where it fails.
 */
class ProtocolSchemaTest {
    private static final Path SCHEMA = Path.of("experiments", "controllers", "protocol.schema.json");
    private static final Path LIBRARY = Path.of("target", "jsonschema");
    private static final String FETCH = "bash .ci/fetch-jsonschema (from the repository root; it needs python3 and PyPI)";
    private static final Wire.Hello EVERYTHING = new Wire.Hello(2, "everything", "1", EnumSet.allOf(Channel.class), true,
            true, true, true);
    private static final Wire.Hello SERVER = new Wire.Hello(2, "server", "1", EnumSet.noneOf(Channel.class), true, true,
            false, false);
    private static final long TICK = 7;
    /** A tick, or a number with a fraction, in a line (whole numbers else, such as fault ids, are kept: they have bounds). */
    private static final Pattern NUMBER = Pattern.compile("\"tick\": ?[0-9]+|-?[0-9]+\\.[0-9]+([Ee]-?[0-9]+)?");

    /**
     * Reads records {"def": name, "line": text} a line; writes for each "ok" or what is wrong with it, and then,
     * for the whole schema, "ok" or what is wrong. NaN and Infinity tokens are not JSON: they are refused before
     * the schema is asked.
     */
    private static final String VALIDATOR = String.join("\n",
            "import json, sys",
            "from jsonschema import Draft202012Validator",
            "schema = json.load(open(sys.argv[1]))",
            "Draft202012Validator.check_schema(schema)",
            "whole = Draft202012Validator(schema)",
            "parts = {}",
            "def of(name):",
            "    if name not in parts:",
            "        part = {k: v for k, v in schema.items() if k != 'anyOf'}",
            "        part['$ref'] = '#/$defs/' + name",
            "        parts[name] = Draft202012Validator(part)",
            "    return parts[name]",
            "def refuse(token):",
            "    raise ValueError('not JSON: ' + token)",
            "def verdict(validator, message):",
            "    errors = sorted(validator.iter_errors(message), key=lambda e: list(e.path))",
            "    return 'ok' if not errors else 'bad: ' + errors[0].message[:200].replace('\\n', ' ')",
            "out = open(sys.argv[3], 'w')",
            "for record in open(sys.argv[2]):",
            "    case = json.loads(record)",
            "    try:",
            "        message = json.loads(case['line'], parse_constant=refuse)",
            "    except ValueError as e:",
            "        out.write('bad: %s\\tbad: %s\\n' % (e, e))",
            "        continue",
            "    out.write(verdict(of(case['def']), message) + '\\t' + verdict(whole, message) + '\\n')",
            "");

    private static List<String> python;

    @TempDir
    Path dir;

    @BeforeAll
    static void needsJsonSchema() {
        boolean present = validatorRuns();
        if (!present && "true".equals(System.getenv("CI"))) {
            fail("python3 with jsonschema is missing on CI: the protocol's schema cannot be checked; run " + FETCH);
        }
        assumeTrue(present, "python3 with jsonschema is missing here, so the protocol's messages are not checked"
                + " against its schema; " + FETCH + " installs it");
    }

    private record Case(String def, String line, String what) {
    }

    @Test
    void everyMessageSitcovTheServerAndThePythonExamplesWriteKeepsTheSchemaAndSitcovReadsTheirCommands()
            throws IOException, ProtocolException {
        List<String> sitcov = sitcovsMessages(EVERYTHING);
        List<Case> cases = new ArrayList<>();
        for (String line : sitcov) {
            Message m = Message.parse(line);
            // every tenth observation, and every one with a null, is enough: the schema takes a while a line
            if (!m.type().equals("observation") || m.integer("tick") % 10 == 0 || line.contains("null")) {
                cases.add(new Case(m.type().equals("hello") ? "sitcovHello" : m.type(), line, "sitcov's " + m.type()));
            }
        }
        assertTrue(sitcov.stream().anyMatch(l -> l.contains("\"distance_to_junction\":null")),
                "a channel without a value (null) is among the observations");
        assertTrue(sitcov.stream().anyMatch(l -> l.contains("\"traffic\":[{")) && sitcov.stream().anyMatch(
                l -> l.contains("\"obstacles\":[{")) && sitcov.stream().anyMatch(l -> l.contains("\"lidar\":[[")),
                "the observations carry tracks, obstacles and hits");
        // each answer with the protocol its conversation speaks
        List<Object[]> answers = new ArrayList<>();
        served(2).forEach(l -> answers.add(new Object[] {l, 2}));
        served(1).forEach(l -> answers.add(new Object[] {l, 1}));
        for (String example : List.of("minimal.py", "lane_follower.py", "route_driver.py")) {
            python(example, sitcov).forEach(l -> answers.add(new Object[] {l, 2}));
        }
        python("minimal.py", protocol1(sitcov)).forEach(l -> answers.add(new Object[] {l, 1}));
        int commands = 0;
        Set<String> shapes = new HashSet<>();
        for (Object[] answer : answers) {
            String line = (String) answer[0];
            boolean two = (int) answer[1] == 2;
            Message m = Message.parse(line);
            String def = m.type().equals("hello") ? "controllerHello" : two ? "command" : "commandProtocol1";
            // answers that differ only in their numbers' values are one case for the schema: it takes a while a line
            if (shapes.add(def + NUMBER.matcher(line).replaceAll("0"))) {
                cases.add(new Case(def, line, "an answer of protocol " + answer[1]));
            }
            if (m.type().equals("hello")) {
                assertEquals(answer[1], Wire.controllerHello(m).protocol(), line);
            } else {
                commands++;
                Wire.command(m, two ? m.integer("tick") : TICK, two, new Command(), switchboard());
            }
        }
        assertTrue(commands > 200, "commands checked: " + commands);
        List<String[]> verdicts = validate(cases);
        for (int i = 0; i < cases.size(); i++) {
            Case c = cases.get(i);
            assertEquals("ok", verdicts.get(i)[0], c.what + " against #/$defs/" + c.def + ": " + c.line);
            assertEquals("ok", verdicts.get(i)[1], c.what + " against the schema: " + c.line);
        }
    }

    /** Commands sitcov refuses (with protocol 2, answering tick 7), each with what is wrong. */
    @Test
    void everySeamFaultsObservationKeepsTheSchema() throws IOException {
        List<Case> cases = new ArrayList<>();
        for (sitcov.seam.SeamFault fault : sitcov.seam.SeamFault.values()) {
            List<String> lines = sitcovsMessages(EVERYTHING, List.of(2L),
                    controllers -> sitcov.seam.SeamControllers.switchedOn(fault, controllers));
            int observations = 0;
            for (String line : lines) {
                // every 25th observation of the run under the fault: the schema takes a while a line
                if (line.startsWith("{\"type\":\"observation\"") && observations++ % 25 == 0) {
                    cases.add(new Case("observation", line, fault.spec() + "'s observation"));
                }
            }
            assertTrue(observations > 50, fault.spec() + ": the run is not trivially short (" + observations + ")");
        }
        List<String[]> verdicts = validate(cases);
        for (int i = 0; i < cases.size(); i++) {
            Case c = cases.get(i);
            assertEquals("ok", verdicts.get(i)[0], c.what + " against #/$defs/" + c.def + ": " + c.line);
            assertEquals("ok", verdicts.get(i)[1], c.what + " against the schema: " + c.line);
        }
    }

    private static final List<String[]> BAD_COMMANDS = List.of(
            bad("no speed_change and no speed", "{\"type\":\"command\",\"tick\":7,\"steering\":0}"),
            bad("speed_change null (NaN)", "{\"type\":\"command\",\"tick\":7,\"speed_change\":null,\"steering\":0}"),
            bad("no steering", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0.1}"),
            bad("steering null (NaN)", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0.1,\"steering\":null}"),
            bad("speed_change +infinity", "{\"type\":\"command\",\"tick\":7,\"speed_change\":1e999,\"steering\":0}"),
            bad("speed -infinity", "{\"type\":\"command\",\"tick\":7,\"speed\":-1e999,\"steering\":0}"),
            bad("steering +infinity", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":1e999}"),
            bad("steering NaN token (not JSON)", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":NaN}"),
            bad("speed_change a string", "{\"type\":\"command\",\"tick\":7,\"speed_change\":\"fast\",\"steering\":0}"),
            bad("steering a boolean", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":true}"),
            bad("no tick (protocol 2)", "{\"type\":\"command\",\"speed_change\":0,\"steering\":0}"),
            bad("tick a string", "{\"type\":\"command\",\"tick\":\"7\",\"speed_change\":0,\"steering\":0}"),
            bad("tick not whole", "{\"type\":\"command\",\"tick\":7.5,\"speed_change\":0,\"steering\":0}"),
            bad("tick null", "{\"type\":\"command\",\"tick\":null,\"speed_change\":0,\"steering\":0}"),
            bad("another type", "{\"type\":\"comand\",\"tick\":7,\"speed_change\":0,\"steering\":0}"),
            bad("no type", "{\"tick\":7,\"speed_change\":0,\"steering\":0}"),
            bad("not an object", "[\"command\",7,0,0]"),
            bad("claim not an array", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"claim\":2}"),
            bad("claim a negative id", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"claim\":[-1]}"),
            bad("release an id not whole", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"release\":[1.5]}"),
            bad("release a string id", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"release\":[\"1\"]}"),
            bad("report not an object", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"report\":\"on\"}"),
            bad("report.overtaking a string",
                    "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"report\":{\"overtaking\":\"yes\"}}"),
            bad("report.lane not a compass direction",
                    "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"report\":{\"lane\":\"up\"}}"),
            bad("report.stage a number",
                    "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"report\":{\"stage\":3}}"),
            bad("faults not an object", "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"faults\":[1]}"),
            bad("faults.reached an unknown fault",
                    "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"faults\":{\"reached\":[20]}}"),
            bad("faults.reached a negative id",
                    "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"faults\":{\"reached\":[-1]}}"),
            bad("faults.effective not a pair",
                    "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"faults\":{\"effective\":[[3]]}}"),
            bad("faults.effective an unknown fault",
                    "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"faults\":{\"effective\":[[20,1]]}}"));

    /** Commands sitcov takes: the schema takes them too. Sitcov ignores members it does not know. */
    private static final List<String> ODD_BUT_GOOD_COMMANDS = List.of(
            "{\"type\":\"command\",\"tick\":7,\"speed\":2.5,\"steering\":-15}",
            "{\"type\":\"command\",\"tick\":7.0,\"speed_change\":-0.4,\"steering\":0}",
            "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"note\":\"members sitcov does not know\"}",
            "{\"type\":\"command\",\"tick\":7,\"speed_change\":0,\"steering\":0,\"claim\":[],\"release\":[0,1],"
                    + "\"report\":{\"lane\":null,\"stage\":null,\"waiting\":false},\"faults\":{\"reached\":[0,19],"
                    + "\"effective\":[[19,2]]}}");

    @Test
    void aBatchedExchangeKeepsTheSchema() throws ControllerStartException, IOException {
        ByteArrayOutputStream toServer = new ByteArrayOutputStream();
        ByteArrayOutputStream fromServer = new ByteArrayOutputStream();
        // the builtin car's server taking batches of 2, every byte each way recorded
        Pipes.Peer recorded = (in, out) -> new ControllerServer(BuiltinCar.FACTORY, "in-process", "test", Set.of(),
                Wire.PROTOCOL, 2).serve(new java.io.FilterInputStream(in) {
                    @Override
                    public int read(byte[] b, int off, int len) throws IOException {
                        int n = super.read(b, off, len);
                        if (n > 0) {
                            synchronized (toServer) {
                                toServer.write(b, off, n);
                            }
                        }
                        return n;
                    }
                }, new java.io.FilterOutputStream(out) {
                    @Override
                    public void write(byte[] b, int off, int len) throws IOException {
                        synchronized (fromServer) {
                            fromServer.write(b, off, len);
                        }
                        out.write(b, off, len);
                    }
                });
        try (BatchingProxy two = Pipes.batching(recorded, 2)) {
            assertEquals(2, two.batch());
            sitcov.judge.BatchedRuns.run(2, two, (i, f) -> new sitcov.judge.LiveRun(MapGenerator.generate(i + 2), i + 2, Set.of(), f));
        }
        List<Case> cases = new ArrayList<>();
        Set<String> types = new HashSet<>();
        int items = 0;
        for (String line : lines(toServer, fromServer)) {
            Message m;
            try {
                m = Message.parse(line);
            } catch (ProtocolException e) {
                throw new AssertionError(line, e);
            }
            types.add(m.type());
            boolean sitcovs = line.contains("\"sitcov\"") || !m.type().equals("hello") && !m.type().equals("commands");
            String def = m.type().equals("hello") ? (sitcovs ? "sitcovHello" : "controllerHello") : m.type();
            if (m.type().equals("observations")) {
                items += (int) line.chars().filter(c -> c == '{').count();
            }
            if (!m.type().equals("hello")) {
                assertTrue(line.contains("\"run\":"), "a batch's message names its run: " + line);
            }
            cases.add(new Case(def, line, "a batched exchange's " + m.type()));
        }
        assertEquals(Set.of("hello", "reset", "observations", "commands", "end"), types);
        assertTrue(items > 20, "observations sent in batches");
        List<String[]> verdicts = validate(cases);
        for (int i = 0; i < cases.size(); i++) {
            Case c = cases.get(i);
            assertEquals("ok", verdicts.get(i)[0], c.what + " against #/$defs/" + c.def + ": " + c.line);
            assertEquals("ok", verdicts.get(i)[1], c.what + " against the schema: " + c.line);
        }
    }

    /** The lines recorded each way, sitcov's first; only every tenth batch of each way (the schema takes a while a line). */
    private static List<String> lines(ByteArrayOutputStream... recorded) {
        List<String> all = new ArrayList<>();
        for (ByteArrayOutputStream r : recorded) {
            String[] lines;
            synchronized (r) {
                lines = r.toString(StandardCharsets.UTF_8).split("\n");
            }
            int batches = 0;
            for (String line : lines) {
                boolean batch = line.startsWith("{\"type\":\"observations\"") || line.startsWith("{\"type\":\"commands\"");
                if (!line.isBlank() && (!batch || batches++ % 10 == 0)) {
                    all.add(line);
                }
            }
        }
        return all;
    }

    @Test
    void theSchemaRefusesEveryCommandSitcovRefusesAndTakesTheOddOnesSitcovTakes() throws IOException, ProtocolException {
        List<Case> cases = new ArrayList<>();
        for (String[] bad : BAD_COMMANDS) {
            assertThrows(ProtocolException.class, () -> read(bad[1]), "sitcov takes the command with " + bad[0]);
            cases.add(new Case("command", bad[1], bad[0]));
        }
        for (String good : ODD_BUT_GOOD_COMMANDS) {
            read(good);
            cases.add(new Case("command", good, "good"));
        }
        List<String[]> verdicts = validate(cases);
        for (int i = 0; i < cases.size(); i++) {
            Case c = cases.get(i);
            if (c.what.equals("good")) {
                assertEquals("ok", verdicts.get(i)[0], "the schema refuses a command sitcov takes: " + c.line);
            } else {
                assertTrue(verdicts.get(i)[0].startsWith("bad: "), "the schema takes the command with " + c.what
                        + ", which sitcov refuses: " + c.line);
            }
        }
    }

    /** sitcov's reading of a command answering tick 7 with protocol 2. */
    private static void read(String line) throws ProtocolException {
        Wire.command(Message.parse(line), TICK, true, new Command(), switchboard());
    }

    private static String[] bad(String what, String line) {
        return new String[] {what, line};
    }

    private static FaultSwitchboard switchboard() {
        return new FaultSwitchboard(Set.of(), () -> TICK);
    }

    // ---- the messages

    /** The lines sitcov writes to a controller that asks for what {@code wants} says, over two runs (the builtin car driving). */
    private static List<String> sitcovsMessages(Wire.Hello wants) {
        return sitcovsMessages(wants, List.of(2L, 3L), controllers -> controllers);
    }

    /** The same over the maps {@code seeds}, the controller wrapped by {@code around} (a seam fault between it and the world). */
    private static List<String> sitcovsMessages(Wire.Hello wants, List<Long> seeds,
                                                java.util.function.UnaryOperator<sitcov.control.ControllerFactory> around) {
        List<String> lines = new ArrayList<>();
        JsonWriter w = new JsonWriter();
        Wire.sitcovHello(w, "test");
        lines.add(w.text().toString());
        for (long seed : seeds) {
            Set<Fault> faults = seed == 2 ? Set.of() : EnumSet.of(Fault.ofId(8), Fault.ofId(16));
            Simulator.run(MapGenerator.generate(seed), seed, Set.of(), RunObserver.NONE, around.apply(run -> {
                ResetMessage.write(w, run, faults);
                lines.add(w.text().toString());
                Controller car = BuiltinCar.FACTORY.start(run);
                return new Controller() {
                    @Override
                    public void step(sitcov.control.Observation now, Command out) {
                        Wire.observation(w, now, wants);
                        lines.add(w.text().toString());
                        car.step(now, out);
                    }

                    @Override
                    public void end(RunEnd how) {
                        Wire.end(w, how);
                        lines.add(w.text().toString());
                    }
                };
            }));
        }
        return lines;
    }

    /** What the builtin car's server answers to {@code sitcov}'s messages, when it speaks at most {@code protocol}. */
    private List<String> served(int protocol) throws IOException, ProtocolException {
        StringBuilder in = new StringBuilder();
        for (String line : sitcovsMessages(SERVER)) {
            in.append(line).append('\n');
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        new ControllerServer(BuiltinCar.FACTORY, "sitcov-builtin", "test", Set.of(), protocol)
                .serve(new ByteArrayInputStream(in.toString().getBytes(StandardCharsets.UTF_8)), out);
        List<String> lines = out.toString(StandardCharsets.UTF_8).lines().toList();
        assertTrue(lines.get(0).startsWith("{\"type\":\"hello\",\"protocol\":" + protocol + ","), lines.get(0));
        assertTrue(lines.stream().anyMatch(l -> l.contains("\"faults\":{\"reached\":[")), "fault activations come back");
        return lines;
    }

    /** What an example controller answers to {@code input}, run as a program. */
    private List<String> python(String script, List<String> input) throws IOException {
        Path in = dir.resolve("input-" + script + ".jsonl");
        Files.write(in, input);
        Process p = new ProcessBuilder(python.get(0), Path.of("experiments", "controllers", script).toString())
                .redirectInput(in.toFile()).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        byte[] out = p.getInputStream().readAllBytes();
        try {
            assertTrue(p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0, script + " failed");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            fail(e);
        }
        List<String> lines = new String(out, StandardCharsets.UTF_8).lines().toList();
        long observations = input.stream().filter(l -> l.contains("\"type\":\"observation\"")).count();
        assertEquals(observations + 1, lines.size(), script + " answers hello and every observation");
        return lines;
    }

    /** The same conversation, sitcov's hello that of a sitcov of protocol 1 only. */
    private static List<String> protocol1(List<String> sitcov) {
        List<String> lines = new ArrayList<>(sitcov);
        lines.set(0, lines.get(0).replace("\"protocol\":2,\"protocols\":[1,2],", "\"protocol\":1,"));
        return lines;
    }

    // ---- the validator

    /** For each case: its verdict against its definition, and against the whole schema. */
    private List<String[]> validate(List<Case> cases) throws IOException {
        Path script = Files.writeString(dir.resolve("validate.py"), VALIDATOR);
        Path records = dir.resolve("cases.jsonl");
        List<String> lines = new ArrayList<>();
        JsonWriter w = new JsonWriter();
        for (Case c : cases) {
            lines.add(w.reset().beginObject().member("def", c.def).member("line", c.line).endObject().text().toString());
        }
        Files.write(records, lines);
        Path verdicts = dir.resolve("verdicts.txt");
        List<String> command = new ArrayList<>(python);
        command.addAll(List.of(script.toString(), SCHEMA.toString(), records.toString(), verdicts.toString()));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        environment(builder);
        Process p = builder.start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        try {
            assertTrue(p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0, "the validator failed: " + output);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            fail(e);
        }
        List<String[]> result = new ArrayList<>();
        for (String line : Files.readAllLines(verdicts)) {
            result.add(line.split("\t", 2));
        }
        assertEquals(cases.size(), result.size());
        return result;
    }

    private static void environment(ProcessBuilder builder) {
        if (Files.isDirectory(LIBRARY)) {
            String old = System.getenv("PYTHONPATH");
            builder.environment().put("PYTHONPATH", LIBRARY.toAbsolutePath() + (old == null ? "" : ":" + old));
        }
    }

    private static boolean validatorRuns() {
        try {
            ProcessBuilder builder = new ProcessBuilder("python3", "-c", "import jsonschema").redirectErrorStream(true);
            environment(builder);
            Process p = builder.start();
            p.getInputStream().readAllBytes();
            boolean ok = p.waitFor(30, TimeUnit.SECONDS) && p.exitValue() == 0;
            python = List.of("python3");
            return ok;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }
}
