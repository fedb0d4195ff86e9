package sitcov.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import java.util.function.LongSupplier;
import org.junit.jupiter.api.Test;

class ModelCopyTest {
    private static final ModelCopy.Sharing NOTHING_MORE = new ModelCopy.Sharing(Set.of());

    /** A mutable model object: a counter, a buffer, friends (one of them possibly itself). Not final: a copy writes them. */
    static final class Node {
        private String name;
        private double[] buffer = new double[3];
        private List<Node> friends = new ArrayList<>();
        private int count;
        private Node self;

        Node(String name) {
            this.name = name;
            this.self = this;
        }
    }

    static final class Holder {
        private Object held;

        Holder(Object held) {
            this.held = held;
        }
    }

    @Test
    void aCopyHasTheOriginalsShapeAndSharesNothingThatCanChange() {
        Node a = new Node("a");
        Node b = new Node("b");
        a.friends.add(b);
        a.friends.add(b);
        b.friends.add(a);
        a.count = 7;
        a.buffer[1] = 2.5;

        Node copy = ModelCopy.of(a, NOTHING_MORE);
        assertNotSame(a, copy);
        assertSame(a.name, copy.name, "a string is a value");
        assertSame(copy, copy.self, "a reference to itself stays one");
        assertSame(copy.friends.get(0), copy.friends.get(1), "an object reached twice is copied once");
        assertSame(copy, copy.friends.get(0).friends.get(0), "a cycle closes on the copy");
        assertEquals(7, copy.count);
        assertEquals(2.5, copy.buffer[1]);

        copy.count = 9;
        copy.buffer[1] = 4;
        copy.friends.get(0).count = 5;
        assertEquals(7, a.count);
        assertEquals(2.5, a.buffer[1]);
        assertEquals(0, b.count, "changing the copy leaves the original as it was");
    }

    @Test
    void whatTheCallerNamesImmutableIsShared() {
        Node shared = new Node("map");
        Holder h = new Holder(shared);
        Holder copy = ModelCopy.of(h, new ModelCopy.Sharing(Set.of(Node.class)));
        assertNotSame(h, copy);
        assertSame(shared, copy.held);
    }

    /** Holds its count in a final field, which a copy would have to write by deep reflection. */
    static final class Counter {
        private final int count;

        Counter(int count) {
            this.count = count;
        }
    }

    @Test
    void aFinalFieldIsRefusedNamingItAndTheFieldThatLedToIt() {
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> ModelCopy.of(new Holder(new Counter(3)), NOTHING_MORE));
        assertTrue(e.getMessage().contains("Counter.count is final") && e.getMessage().contains("in Holder.held"),
                e.getMessage());
        Counter shared = new Counter(3);
        assertSame(shared, ModelCopy.of(new Holder(shared), new ModelCopy.Sharing(Set.of(Counter.class))).held,
                "a class named immutable may keep its fields final: it is shared, never written");
    }

    @Test
    void onlyTheClassesNamedAreSharedNotTheirNeighbours() {
        Node n = new Node("n");
        Holder copy = ModelCopy.of(new Holder(n), new ModelCopy.Sharing(Set.of(Counter.class)));
        assertNotSame(n, copy.held, "a class of the same package as one named is copied");
    }

    @Test
    void aLambdaThatCapturedStateIsRefusedNamingTheFieldThatHoldsIt() {
        Node n = new Node("n");
        LongSupplier captured = () -> n.count;
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> ModelCopy.of(new Holder(captured), NOTHING_MORE));
        assertTrue(e.getMessage().contains("a lambda that captured state") && e.getMessage().contains("Holder.held"),
                e.getMessage());
    }

    @Test
    void aReadOnlyViewIsRefusedBecauseTheListItViewsCannotBeFound() {
        List<Node> nodes = new ArrayList<>(List.of(new Node("x")));
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> ModelCopy.of(new Holder(Collections.unmodifiableList(nodes)), NOTHING_MORE));
        assertTrue(e.getMessage().contains("Unmodifiable"), e.getMessage());
    }

    @Test
    void aRandomStreamCopiedDrawsOnAsTheOriginalDoes() {
        RandomStreams streams = new RandomStreams(11);
        streams.stream("a").nextLong();
        RandomStreams copy = ModelCopy.of(streams, NOTHING_MORE);
        assertEquals(streams.stream("a").nextLong(), copy.stream("a").nextLong());
        assertEquals(streams.stream("b").nextDouble(), copy.stream("b").nextDouble());
    }

    record Reading(double value, String unit) {
    }

    record Buffer(double[] values) {
    }

    @Test
    void aRecordOfValuesIsSharedAndOneHoldingWhatMayChangeIsRefused() {
        Reading reading = new Reading(2, "m");
        Holder copy = ModelCopy.of(new Holder(reading), NOTHING_MORE);
        assertSame(reading, copy.held);
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> ModelCopy.of(new Holder(new Buffer(new double[2])), NOTHING_MORE));
        assertTrue(e.getMessage().contains("record") && e.getMessage().contains("values (double[]) may change"),
                e.getMessage());
    }
}
