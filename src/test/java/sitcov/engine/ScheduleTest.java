package sitcov.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;

class ScheduleTest {

    private final List<String> log = new ArrayList<>();

    private Steppable logs(String name) {
        return state -> log.add(state.tick() + ":" + name);
    }

    @Test
    void eventsRunInTickOrderThenByOrdering() {
        SimState state = new SimState(7);
        Schedule schedule = state.schedule();
        schedule.scheduleOnce(2, 0, logs("late"));
        schedule.scheduleOnce(1, 1, logs("detector"));
        schedule.scheduleOnce(1, 0, logs("car"));
        schedule.scheduleOnce(0, 5, logs("first"));

        while (state.step()) {
            // run to the end
        }

        assertEquals(List.of("0:first", "1:car", "1:detector", "2:late"), log);
    }

    @Test
    void stepRunsOnlyTheNextTickAndReportsWhenNothingIsLeft() {
        SimState state = new SimState(7);
        state.schedule().scheduleOnce(4, 0, logs("a"));
        state.schedule().scheduleOnce(9, 0, logs("b"));

        assertTrue(state.step());
        assertEquals(List.of("4:a"), log);
        assertEquals(4, state.tick());
        assertTrue(state.step());
        assertTrue(state.schedule().isEmpty());
        assertFalse(state.step());
        assertEquals(9, state.tick());
    }

    @Test
    void theShuffleOfEqualOrderingsIsTheSameForTheSameSeedAndDiffersForAnother() {
        List<String> first = orderOfTenAgentsOverFiveTicks(42);
        List<String> again = orderOfTenAgentsOverFiveTicks(42);
        List<String> other = orderOfTenAgentsOverFiveTicks(43);

        assertEquals(first, again);
        assertNotEquals(first, other);
    }

    @Test
    void theShuffleChangesFromTickToTick() {
        List<String> order = orderOfTenAgentsOverFiveTicks(42);
        List<String> tick0 = order.subList(0, 10).stream().map(s -> s.substring(2)).toList();
        List<String> tick1 = order.subList(10, 20).stream().map(s -> s.substring(2)).toList();

        assertNotEquals(tick0, tick1, "agents of equal ordering must be reshuffled every tick");
    }

    @Test
    void theShuffleNeverMixesOrderings() {
        SimState state = new SimState(3);
        for (int i = 0; i < 6; i++) {
            state.schedule().scheduleRepeating(0, 1, 1, logs("detector" + i));
            state.schedule().scheduleRepeating(0, 0, 1, logs("car" + i));
        }
        for (int t = 0; t < 20; t++) {
            state.step();
            List<String> tick = log.subList(log.size() - 12, log.size());
            assertTrue(tick.subList(0, 6).stream().allMatch(s -> s.contains("car")), tick.toString());
            assertTrue(tick.subList(6, 12).stream().allMatch(s -> s.contains("detector")), tick.toString());
        }
    }

    private List<String> orderOfTenAgentsOverFiveTicks(long seed) {
        SimState state = new SimState(seed);
        List<String> order = new ArrayList<>();
        IntStream.range(0, 10).forEach(i ->
                state.schedule().scheduleRepeating(0, 0, 1, s -> order.add(s.tick() + ":" + i)));
        for (int t = 0; t < 5; t++) {
            state.step();
        }
        return order;
    }

    @Test
    void aRepeatingEventRunsEveryIntervalUntilStoppedAndNeverAgainAfter() {
        SimState state = new SimState(1);
        Stoppable handle = state.schedule().scheduleRepeating(0, 0, 2, logs("blink"));
        state.schedule().scheduleRepeating(0, 1, 1, logs("clock"));

        for (int t = 0; t < 4; t++) {
            state.step();
        }
        handle.stop();
        handle.stop();
        for (int t = 0; t < 6; t++) {
            state.step();
        }

        assertEquals(List.of("0:blink", "2:blink"), log.stream().filter(s -> s.endsWith("blink")).toList());
        assertEquals(10, log.stream().filter(s -> s.endsWith("clock")).count());
    }

    @Test
    void anEventStoppedEarlierInTheSameTickDoesNotRun() {
        SimState state = new SimState(1);
        Stoppable[] victim = new Stoppable[1];
        state.schedule().scheduleRepeating(0, 0, 1, s -> victim[0].stop());
        victim[0] = state.schedule().scheduleRepeating(0, 1, 1, logs("victim"));

        state.step();
        state.step();

        assertEquals(List.of(), log);
    }

    @Test
    void stoppingTheLastRepeatingEventEmptiesTheSchedule() {
        SimState state = new SimState(1);
        Stoppable handle = state.schedule().scheduleRepeating(logs("x"), 0);
        assertFalse(state.schedule().isEmpty());

        handle.stop();

        assertTrue(state.schedule().isEmpty());
        assertFalse(state.step());
    }

    @Test
    void schedulingInThePastOrNowIsRefusedWithAClearMessage() {
        SimState state = new SimState(1);
        state.schedule().scheduleOnce(5, 0, logs("a"));
        state.step();

        IllegalArgumentException now = assertThrows(IllegalArgumentException.class,
                () -> state.schedule().scheduleOnce(5, 0, logs("b")));
        IllegalArgumentException past = assertThrows(IllegalArgumentException.class,
                () -> state.schedule().scheduleRepeating(2, 0, 1, logs("c")));

        assertEquals("cannot schedule an event at tick 5: the schedule is at tick 5, so the earliest tick is 6",
                now.getMessage());
        assertTrue(past.getMessage().contains("at tick 2"), past.getMessage());
    }

    @Test
    void negativeTicksAndZeroIntervalsAreRefused() {
        Schedule schedule = new SimState(1).schedule();

        assertThrows(IllegalArgumentException.class, () -> schedule.scheduleOnce(-1, 0, s -> { }));
        assertThrows(IllegalArgumentException.class, () -> schedule.scheduleRepeating(0, 0, 0, s -> { }));
    }

    @Test
    void schedulingWithoutATickMeansTheNextTick() {
        SimState state = new SimState(1);
        state.schedule().scheduleOnce(3, 0, s -> s.schedule().scheduleOnce(logs("follow-up"), 0));

        state.step();
        state.step();

        assertEquals(List.of("4:follow-up"), log);
    }

    @Test
    void clearingDuringATickStopsTheRestOfThatTickAndEverythingAfter() {
        SimState state = new SimState(1);
        state.schedule().scheduleRepeating(0, 0, 1, s -> {
            log.add("ender");
            s.schedule().clear();
        });
        state.schedule().scheduleRepeating(0, 1, 1, logs("later"));

        assertTrue(state.step());

        assertEquals(List.of("ender"), log);
        assertTrue(state.schedule().isEmpty());
        assertFalse(state.step());
    }

    @Test
    void aPausedTickGoesOnWhereItPausedAndRunsAsItWouldHaveWhole() {
        List<String> whole = tenAgentsOverThreeTicks(false);
        log.clear();
        List<String> paused = tenAgentsOverThreeTicks(true);
        assertEquals(whole, paused.stream().filter(e -> !e.endsWith("again")).toList());
        // agent 3 paused each tick, stepped again first when the tick went on, once a tick
        assertEquals(3, paused.stream().filter(e -> e.endsWith("3 again")).count());
        for (int tick = 0; tick < 3; tick++) {
            int first = paused.indexOf(tick + ":agent 3");
            assertEquals(tick + ":agent 3 again", paused.get(first + 1));
        }
    }

    /** Ten agents of one ordering, shuffled, over ticks 0..2; with {@code pausing}, agent 3 pauses its tick every time. */
    private List<String> tenAgentsOverThreeTicks(boolean pausing) {
        SimState state = new SimState(11);
        Schedule schedule = state.schedule();
        for (int i = 0; i < 10; i++) {
            String name = "agent " + i;
            boolean pauses = pausing && i == 3;
            boolean[] waiting = {false};
            schedule.scheduleRepeating(0, 0, 1, s -> {
                if (waiting[0]) {
                    waiting[0] = false;
                    log.add(s.tick() + ":" + name + " again");
                    return;
                }
                log.add(s.tick() + ":" + name);
                if (pauses) {
                    waiting[0] = true;
                    s.schedule().pause();
                }
            });
        }
        while (state.tick() < 2 || schedule.isPaused()) {
            boolean pausedBefore = schedule.isPaused();
            state.step();
            assertTrue(!pausedBefore || !schedule.isPaused(), "a tick goes on after its pause");
        }
        return new ArrayList<>(log);
    }
}
