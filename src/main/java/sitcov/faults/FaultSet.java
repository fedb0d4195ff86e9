package sitcov.faults;

import java.util.EnumSet;
import java.util.Set;
import java.util.StringJoiner;

/**
 * Fault sets as users write them: {@code PAPER}, {@code ALL}, {@code NONE}, ids, ranges such as
 * {@code 8-13}, and exclusions such as {@code ALL,-0}, separated by commas and read left to right.
 */
public final class FaultSet {
    private FaultSet() {
    }

    /** The seven faults of the paper's Table 1. */
    public static Set<Fault> paper() {
        EnumSet<Fault> paper = EnumSet.noneOf(Fault.class);
        for (Fault f : Fault.values()) {
            f.paperId().ifPresent(id -> paper.add(f));
        }
        return paper;
    }

    /**
     * The set {@code text} names.
     *
     * @throws IllegalArgumentException naming the part that is wrong and what is accepted
     */
    public static Set<Fault> parse(String text) {
        if (text == null || text.isBlank()) {
            throw new IllegalArgumentException("the fault set is empty; " + accepted());
        }
        EnumSet<Fault> set = EnumSet.noneOf(Fault.class);
        String[] parts = text.split(",", -1);
        for (String raw : parts) {
            String part = raw.strip();
            boolean exclude = part.startsWith("-") && !part.isEmpty();
            if (exclude && raw == parts[0]) {
                throw new IllegalArgumentException("'" + part + "' removes faults, but nothing comes before it to remove"
                        + " them from; start with the set to remove them from, e.g. ALL," + part);
            }
            String body = exclude ? part.substring(1).strip() : part;
            Set<Fault> named = named(body, part);
            if (exclude) {
                set.removeAll(named);
            } else {
                set.addAll(named);
            }
        }
        return set;
    }

    /** The set written back in the shortest of the accepted forms: {@code NONE}, {@code ALL}, {@code PAPER} or ids and ranges. */
    public static String format(Set<Fault> faults) {
        if (faults.isEmpty()) {
            return "NONE";
        }
        if (faults.size() == Fault.values().length) {
            return "ALL";
        }
        if (faults.equals(paper())) {
            return "PAPER";
        }
        StringJoiner parts = new StringJoiner(",");
        int[] ids = faults.stream().mapToInt(Fault::id).sorted().toArray();
        for (int i = 0; i < ids.length; ) {
            int j = i;
            while (j + 1 < ids.length && ids[j + 1] == ids[j] + 1) {
                j++;
            }
            parts.add(j == i ? Integer.toString(ids[i]) : ids[i] + "-" + ids[j]);
            i = j + 1;
        }
        return parts.toString();
    }

    private static Set<Fault> named(String body, String part) {
        switch (body.toUpperCase(java.util.Locale.ROOT)) {
            case "ALL":
                return EnumSet.allOf(Fault.class);
            case "NONE":
                return EnumSet.noneOf(Fault.class);
            case "PAPER":
                return paper();
            default:
                break;
        }
        int dash = body.indexOf('-', 1);
        if (dash > 0) {
            int from = id(body.substring(0, dash), part);
            int to = id(body.substring(dash + 1), part);
            if (from > to) {
                throw new IllegalArgumentException("the range '" + part + "' runs backwards; write it low-high, e.g. 8-13");
            }
            EnumSet<Fault> range = EnumSet.noneOf(Fault.class);
            for (int id = from; id <= to; id++) {
                range.add(Fault.ofId(id));
            }
            return range;
        }
        return EnumSet.of(Fault.ofId(id(body, part)));
    }

    private static int id(String digits, String part) {
        String d = digits.strip();
        int last = Fault.values().length - 1;
        if (!d.matches("\\d{1,9}") || Integer.parseInt(d) > last) {
            throw new IllegalArgumentException("'" + part + "' is not a fault; " + accepted());
        }
        return Integer.parseInt(d);
    }

    private static String accepted() {
        return "write PAPER, ALL, NONE, ids 0-" + (Fault.values().length - 1)
                + ", ranges such as 8-13 and exclusions such as ALL,-0 (comma-separated)";
    }
}
