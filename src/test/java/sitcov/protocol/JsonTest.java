package sitcov.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The protocol's JSON: doubles cross bit for bit, seeds stay exact, and what is not JSON is refused with a place. */
class JsonTest {

    @Test
    void everyDoubleWrittenIsReadBackBitForBit() throws ProtocolException {
        SplittableRandom random = new SplittableRandom(7);
        JsonWriter w = new JsonWriter();
        for (int i = 0; i < 20_000; i++) {
            // raw bit patterns reach subnormals, huge and tiny exponents; the rest are everyday values
            double d = i % 2 == 0 ? Double.longBitsToDouble(random.nextLong()) : random.nextDouble(-500, 500);
            if (!Double.isFinite(d)) {
                continue;
            }
            w.reset().value(d);
            Number back = (Number) Json.parse(w.text().toString());
            assertEquals(Double.doubleToRawLongBits(d), Double.doubleToRawLongBits(back.doubleValue()), w.text().toString());
        }
    }

    @Test
    void negativeZeroAndWholeNumbersKeepTheirValue() throws ProtocolException {
        JsonWriter w = new JsonWriter();
        assertEquals("-0.0", w.reset().value(-0.0).text().toString());
        assertEquals("3", w.reset().value(3.0).text().toString());
        assertEquals(Double.doubleToRawLongBits(-0.0),
                Double.doubleToRawLongBits(((Number) Json.parse("-0.0")).doubleValue()));
    }

    @Test
    void nanIsWrittenAsNullAndTheInfinitiesAsNumbersEveryReaderParses() {
        JsonWriter w = new JsonWriter();
        assertEquals("[null,1e999,-1e999]", w.reset().beginArray().value(Double.NaN)
                .value(Double.POSITIVE_INFINITY).value(Double.NEGATIVE_INFINITY).endArray().text().toString());
    }

    @Test
    void a64BitSeedIsReadExactly() throws ProtocolException {
        JsonWriter w = new JsonWriter();
        long seed = -8_070_450_532_247_928_833L;
        w.reset().beginObject().member("seed", seed).endObject();
        assertEquals(Map.of("seed", seed), Json.parse(w.text().toString()));
    }

    @Test
    void objectsArraysStringsAndLiteralsAreReadAsJavaValues() throws ProtocolException {
        Object v = Json.parse(" {\"a\": [1, 2.5, \"x\\n\\u00e9\"], \"b\": {\"c\": true, \"d\": null}} ");
        Map<String, Object> inner = new java.util.HashMap<>();
        inner.put("c", true);
        inner.put("d", null);
        assertEquals(Map.of("a", List.of(1L, 2.5, "x\né"), "b", inner), v);
    }

    @Test
    void stringsAreEscapedSoThatTheyReadBack() throws ProtocolException {
        String tricky = "quote \" backslash \\ tab \t newline \n bell \u0007";
        JsonWriter w = new JsonWriter();
        assertEquals(tricky, Json.parse(w.reset().value(tricky).text().toString()));
    }

    @Test
    void textThatIsNotJsonIsRefusedWithWhereItWentWrong() {
        ProtocolException e = assertThrows(ProtocolException.class, () -> Json.parse("{\"a\": tru}"));
        assertEquals("not JSON: unexpected 't' at character 7", e.getMessage());
        assertThrows(ProtocolException.class, () -> Json.parse("[1, 2"));
        assertThrows(ProtocolException.class, () -> Json.parse("{} extra"));
        assertThrows(ProtocolException.class, () -> Json.parse("01x"));
    }

    @Test
    void aCommandWithANonFiniteSteeringIsRefusedByName() throws ProtocolException {
        Message m = Message.parse("{\"type\":\"command\",\"speed_change\":0,\"steering\":NaN}");
        ProtocolException e = assertThrows(ProtocolException.class, () -> m.number("steering"));
        assertTrue(e.getMessage().startsWith("command.steering must be a finite number"), e.getMessage());
    }
}
