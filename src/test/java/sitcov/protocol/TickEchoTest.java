package sitcov.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.control.ControllerFailure;
import sitcov.faults.Fault;
import sitcov.judge.LiveRun;
import sitcov.judge.RunObserver;
import sitcov.judge.RunRecord;
import sitcov.judge.Simulator;
import sitcov.oracle.Outcome;
import sitcov.world.MapGenerator;
import sitcov.world.Situations;
import sitcov.world.WorldMap;

/**
 * Protocol 2's lockstep: every command echoes its observation's tick. A command for another tick
 * and a second command for one observation end the run with CONTROLLER_ERROR naming both ticks,
 * the moment the line is read (no timing involved); protocol 1, without the echo, is still
 * accepted, and runs are the same with either. The controllers are scripted peers on a thread,
 * answering each observation with full throttle straight on (which takes the car to the Target on
 * the straight road), but for the line they get wrong.
 */
class TickEchoTest {
    private static final WorldMap STRAIGHT = Situations.withoutTraffic(Situations.straight(List.of()));

    /** What a scripted controller writes for the observation of {@code tick}: lines, each with its newline. */
    @FunctionalInterface
    private interface Answer {
        String lines(long tick);
    }

    private static String command(long tick) {
        return "{\"type\":\"command\",\"tick\":" + tick + ",\"speed_change\":0.1,\"steering\":0}\n";
    }

    @Test
    void aControllerThatEchoesEveryTickDrivesToTheTarget() {
        LiveRun run = runToEnd(2, TickEchoTest::command);
        assertEquals(Outcome.TARGET_REACHED, run.record().result().outcome());
        assertNull(run.scene().autonomousCar().failure());
    }

    @Test
    void aFaultReportFromAControllerThatHasNoSeededFaultsIsAControllerError() {
        LiveRun run = runToEnd(2, tick -> tick == 5
                ? "{\"type\":\"command\",\"tick\":5,\"speed_change\":0.1,\"steering\":0,\"faults\":{\"reached\":[3]}}\n"
                : command(tick));
        assertEquals(Outcome.CONTROLLER_ERROR, run.record().result().outcome());
        assertEquals(6, run.record().result().ticks(), "it failed in tick 5, the sixth");
        assertTrue(failure(run).contains("it reported fault activations, but its hello did not say it has sitcov's seeded"
                + " faults"), failure(run));
    }

    @Test
    void aCommandForAnotherTickIsAControllerErrorNamingBothTicks() {
        LiveRun run = runToEnd(2, tick -> command(tick == 42 ? 41 : tick));
        assertEquals(Outcome.CONTROLLER_ERROR, run.record().result().outcome());
        assertEquals(43, run.record().result().ticks());
        assertTrue(failure(run).contains("at tick 42 it wrote '{\"type\":\"command\",\"tick\":41,")
                && failure(run).contains(": the command answers tick 41, the observation was tick 42"), failure(run));
    }

    @Test
    void aCommandAheadOfItsObservationIsAControllerErrorToo() {
        LiveRun run = runToEnd(2, tick -> command(tick == 7 ? 8 : tick));
        assertEquals(Outcome.CONTROLLER_ERROR, run.record().result().outcome());
        assertTrue(failure(run).endsWith("the command answers tick 8, the observation was tick 7"), failure(run));
    }

    @Test
    void aSecondCommandForOneObservationIsCaughtAtTheNextObservationNamingBothTicks() {
        // the stray line waits in the pipe; it is read as the answer to observation 42, and its tick gives it away
        LiveRun run = runToEnd(2, tick -> tick == 41 ? command(41) + command(41) : command(tick));
        assertEquals(Outcome.CONTROLLER_ERROR, run.record().result().outcome());
        assertEquals(43, run.record().result().ticks());
        assertTrue(failure(run).contains("the command answers tick 41, the observation was tick 42 (a command written"
                + " for an earlier observation: each observation gets exactly one command)"), failure(run));
    }

    @Test
    void aProtocol2CommandWithoutItsTickIsAControllerError() {
        LiveRun run = runToEnd(2, tick -> "{\"type\":\"command\",\"speed_change\":0.1,\"steering\":0}\n");
        assertEquals(Outcome.CONTROLLER_ERROR, run.record().result().outcome());
        assertTrue(failure(run).contains("at tick 0 it wrote") && failure(run).contains(
                "command.tick is missing: with protocol 2 a command echoes the tick of the observation it answers (0)"),
                failure(run));
    }

    @Test
    void aTickThatIsNotAWholeNumberIsAControllerError() {
        LiveRun run = runToEnd(2, tick -> "{\"type\":\"command\",\"tick\":\"0\",\"speed_change\":0.1,\"steering\":0}\n");
        assertEquals(Outcome.CONTROLLER_ERROR, run.record().result().outcome());
        assertTrue(failure(run).endsWith("command.tick must be a whole number"), failure(run));
    }

    @Test
    void withTheDeprecatedProtocol1TheTickIsNotCheckedAndAStrayCommandCannotBeDetected() {
        // a stray line is taken as the next observation's command: the run goes on, a tick behind
        LiveRun plain = runToEnd(1, tick -> "{\"type\":\"command\",\"speed_change\":0.1,\"steering\":0}\n");
        assertEquals(Outcome.TARGET_REACHED, plain.record().result().outcome());
        LiveRun stray = runToEnd(1, tick -> tick == 5 ? command(99) + command(5) : command(tick));
        assertEquals(Outcome.TARGET_REACHED, stray.record().result().outcome());
        assertNull(stray.scene().autonomousCar().failure());
    }

    @Test
    void aControllerHelloOfAProtocolSitcovDoesNotSpeakFailsTheHandshake() {
        ProxyFactory three = Pipes.connecting((in, out) -> {
            Lines lines = new Lines(in, out);
            lines.read();
            write(out, "{\"type\":\"hello\",\"protocol\":3}");
            while (lines.read() != null) {
                // until sitcov lets go
            }
        });
        try (three) {
            LiveRun run = new LiveRun(STRAIGHT, 1, Set.of(), three);
            while (run.step()) {
                // to the end
            }
            assertEquals(Outcome.CONTROLLER_ERROR, run.record().result().outcome());
            assertTrue(failure(run).endsWith("failed the handshake: it speaks protocol 3; this sitcov speaks protocols 1"
                    + " and 2"), failure(run));
        }
    }

    @Test
    void runsAreTheSameOverProtocol1AndProtocol2() {
        try (ProxyFactory one = Pipes.serving(BuiltinCar.FACTORY, Set.of(), 1);
             ProxyFactory two = Pipes.serving(BuiltinCar.FACTORY, Set.of(), 2)) {
            for (long seed = 1; seed <= 3; seed++) {
                WorldMap map = MapGenerator.generate(seed);
                Set<Fault> faults = seed == 1 ? Set.of(Fault.ofId(16)) : Set.of();
                RunRecord overOne = Simulator.run(map, seed, faults, RunObserver.NONE, one);
                RunRecord overTwo = Simulator.run(map, seed, faults, RunObserver.NONE, two);
                assertEquals(overOne, overTwo, "seed " + seed);
            }
        }
    }

    /** One run on the straight road with a scripted controller that says it speaks {@code protocol}. */
    private static LiveRun runToEnd(int protocol, Answer answer) {
        try (ProxyFactory controllers = Pipes.connecting((in, out) -> script(in, out, protocol, answer))) {
            LiveRun run = new LiveRun(STRAIGHT, 1, Set.of(), controllers);
            while (run.step()) {
                // to the end
            }
            return run;
        }
    }

    private static void script(InputStream in, OutputStream out, int protocol, Answer answer)
            throws IOException, ProtocolException {
        Lines lines = new Lines(in, out);
        for (String line = lines.read(); line != null; line = lines.read()) {
            Message m = Message.parse(line);
            switch (m.type()) {
                case "hello" -> write(out, "{\"type\":\"hello\",\"protocol\":" + protocol + "}");
                case "observation" -> {
                    for (String a : answer.lines(m.integer("tick")).split("\n")) {
                        write(out, a);
                    }
                }
                default -> {
                    // reset, end: no answer
                }
            }
        }
    }

    private static void write(OutputStream out, String line) throws IOException {
        out.write((line + "\n").getBytes(StandardCharsets.UTF_8));
        out.flush();
    }

    private static String failure(LiveRun run) {
        ControllerFailure f = run.scene().autonomousCar().failure();
        return f == null ? "no failure" : f.getMessage();
    }
}
