package sitcov.protocol;

import java.util.List;
import java.util.Map;

/**
 * One protocol message as read: a JSON object with a string "type", and typed access to its
 * members that names what is wrong with a member in a {@link ProtocolException}.
 */
final class Message {
    private final String type;
    private final Map<String, Object> members;
    /** The message this one is a member of (null at the top), and its name there: for error messages only. */
    private final Message parent;
    private final String name;
    private final int index;

    private Message(String type, Map<String, Object> members, Message parent, String name, int index) {
        this.type = type;
        this.members = members;
        this.parent = parent;
        this.name = name;
        this.index = index;
    }

    /** Where the message sits, e.g. "observation.traffic[2]"; worked out only for an error. */
    private String where() {
        if (parent == null) {
            return type;
        }
        return parent.where() + "." + name + (index < 0 ? "" : "[" + index + "]");
    }

    /** The message a line holds; refused when it is not a JSON object with a string "type". */
    static Message parse(String line) throws ProtocolException {
        Object value = Json.parse(line);
        if (!(value instanceof Map<?, ?> map)) {
            throw new ProtocolException("a message must be a JSON object, got " + shorten(line));
        }
        Object type = map.get("type");
        if (!(type instanceof String name)) {
            throw new ProtocolException("a message needs a string \"type\", got " + shorten(line));
        }
        @SuppressWarnings("unchecked")
        Map<String, Object> members = (Map<String, Object>) map;
        return new Message(name, members, null, null, -1);
    }

    String type() {
        return type;
    }

    /** Refuses a message of another type than {@code expected}. */
    Message expect(String expected) throws ProtocolException {
        if (!type.equals(expected)) {
            throw new ProtocolException("expected a \"" + expected + "\" message, got \"" + type + "\"");
        }
        return this;
    }

    boolean has(String name) {
        return members.get(name) != null;
    }

    /** A finite number. */
    double number(String name) throws ProtocolException {
        Object v = members.get(name);
        if (!(v instanceof Number n)) {
            throw wrong(name, v == null && !members.containsKey(name) ? "is missing" : "must be a number");
        }
        double d = n.doubleValue();
        if (!Double.isFinite(d)) {
            throw wrong(name, "must be a finite number, got " + d);
        }
        return d;
    }

    /** A number that may be null (NaN) or ±1e999. */
    double numberOrNaN(String name) throws ProtocolException {
        Object v = members.get(name);
        if (v == null) {
            if (!members.containsKey(name)) {
                throw wrong(name, "is missing");
            }
            return Double.NaN;
        }
        if (!(v instanceof Number n)) {
            throw wrong(name, "must be a number or null");
        }
        return n.doubleValue();
    }

    /** A whole number. */
    long integer(String name) throws ProtocolException {
        return whole(members.get(name), name);
    }

    boolean flag(String name) throws ProtocolException {
        Object v = members.get(name);
        if (!(v instanceof Boolean b)) {
            throw wrong(name, v == null && !members.containsKey(name) ? "is missing" : "must be true or false");
        }
        return b;
    }

    /** An optional flag: false when absent or null. */
    boolean optionalFlag(String name) throws ProtocolException {
        return has(name) && flag(name);
    }

    String text(String name) throws ProtocolException {
        Object v = members.get(name);
        if (!(v instanceof String s)) {
            throw wrong(name, v == null && !members.containsKey(name) ? "is missing" : "must be a string");
        }
        return s;
    }

    /** An optional string: null when absent or null. */
    String optionalText(String name) throws ProtocolException {
        return has(name) ? text(name) : null;
    }

    List<Object> list(String name) throws ProtocolException {
        Object v = members.get(name);
        if (!(v instanceof List<?> list)) {
            throw wrong(name, v == null && !members.containsKey(name) ? "is missing" : "must be an array");
        }
        @SuppressWarnings("unchecked")
        List<Object> items = (List<Object>) list;
        return items;
    }

    /** An optional array: empty when absent or null. */
    List<Object> optionalList(String name) throws ProtocolException {
        return has(name) ? list(name) : List.of();
    }

    Message object(String name) throws ProtocolException {
        Object v = members.get(name);
        if (!(v instanceof Map<?, ?> map)) {
            throw wrong(name, v == null && !members.containsKey(name) ? "is missing" : "must be an object");
        }
        return of(map, this, name, -1);
    }

    /** The object at {@code index} of an array member {@code name}. */
    Message item(List<Object> items, int index, String name) throws ProtocolException {
        Object v = items.get(index);
        if (!(v instanceof Map<?, ?> map)) {
            throw new ProtocolException(where() + "." + name + "[" + index + "] must be an object");
        }
        return of(map, this, name, index);
    }

    /** The message at {@code index} of an array member {@code name}: an object with a string "type" (an item of a batch). */
    Message messageAt(List<Object> items, int index, String name) throws ProtocolException {
        Object v = items.get(index);
        if (!(v instanceof Map<?, ?> map) || !(map.get("type") instanceof String type)) {
            throw new ProtocolException(where() + "." + name + "[" + index + "] must be an object with a string \"type\"");
        }
        @SuppressWarnings("unchecked")
        Map<String, Object> members = (Map<String, Object>) map;
        return new Message(type, members, this, name, index);
    }

    /** The whole number at {@code index} of an array member {@code name}. */
    long wholeAt(List<Object> items, int index, String name) throws ProtocolException {
        Object v = items.get(index);
        if (v instanceof Long n) {
            return n;
        }
        return whole(v, name + "[" + index + "]");
    }

    /** The number at {@code index} of an array member {@code name}, finite. */
    double numberAt(List<Object> items, int index, String name) throws ProtocolException {
        Object v = items.get(index);
        if (!(v instanceof Number n) || !Double.isFinite(n.doubleValue())) {
            throw wrong(name + "[" + index + "]", "must be a finite number");
        }
        return n.doubleValue();
    }

    /** The members of an object member, by name (for channels and the like). */
    Map<String, Object> members() {
        return members;
    }

    private long whole(Object v, String name) throws ProtocolException {
        if (v instanceof Long n) {
            return n;
        }
        if (!(v instanceof Double d) || d != Math.rint(d) || Math.abs(d) > 9.007199254740992E15) {
            throw wrong(name, "must be a whole number");
        }
        return (long) d.doubleValue();
    }

    private ProtocolException wrong(String name, String what) {
        return new ProtocolException(where() + "." + name + " " + what);
    }

    private static Message of(Map<?, ?> map, Message parent, String name, int index) {
        @SuppressWarnings("unchecked")
        Map<String, Object> members = (Map<String, Object>) map;
        return new Message(null, members, parent, name, index);
    }

    /** At most 80 characters of {@code text}, for messages. */
    static String shorten(String text) {
        String one = text.strip();
        return one.length() <= 80 ? "'" + one + "'" : "'" + one.substring(0, 77) + "...'";
    }
}
