package sitcov.judge;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import sitcov.faults.Fault;
import sitcov.faults.FaultSet;
import sitcov.seam.SeamFault;

/**
 * Variants as a preset's {@code variants=} key writes them: specs separated by {@code ;} (outside
 * quotes), each {@code builtin:F} (one seeded fault of the builtin reference; with several faults, the
 * builtin car with all of them planted, as another controller), {@code builtin} (the builtin car, as
 * another controller), {@code seam:NAME} (a seam fault of the reference; {@code seam:ALL}, the whole
 * catalogue), {@code exec:COMMAND ARGS…} or {@code java:NAME}; or the whole list {@code none}
 * (no variants: the experiment seeks the reference's own failures).
 */
public final class VariantList {
    /** The list of no variants. */
    public static final String NONE = "none";
    private static final List<String> SOURCES = List.of("builtin:", "exec:", "java:", "seam:");

    private VariantList() {
    }

    /**
     * The variants {@code text} lists, numbered ({@link Variant#number}).
     *
     * @throws IllegalArgumentException naming the spec that is wrong and what is accepted
     */
    public static List<Variant> parse(String text) {
        String t = text.strip();
        if (t.equals(NONE)) {
            return List.of();
        }
        if (namesNone(t)) {
            throw new IllegalArgumentException("'" + t + "' names no variant; name at least one, e.g. builtin:16, separated"
                    + " by ';', or write " + NONE + " for none");
        }
        List<String> specs = new ArrayList<>();
        for (String raw : split(t)) {
            String spec = raw.strip();
            if (spec.isEmpty()) {
                throw new IllegalArgumentException("variants= has an empty entry in '" + text.strip()
                        + "'; separate variants by one ';'");
            }
            if (spec.equals(NONE)) {
                throw new IllegalArgumentException("variants=none stands alone: it means no variants");
            }
            if (!spec.equals("builtin") && SOURCES.stream().noneMatch(spec::startsWith)) {
                throw new IllegalArgumentException("a variant is builtin:FAULTS, builtin, seam:NAME, exec:COMMAND ARGS or java:NAME"
                        + " (or the whole list is none), not '" + spec + "'");
            }
            if (SeamFault.names(spec)) {
                // seam:ALL is the catalogue, one variant a fault
                SeamFault.parse(spec).forEach(f -> specs.add(f.spec()));
            } else {
                specs.add(spec);
            }
        }
        return Variant.number(specs, VariantList::seeded);
    }

    /** Whether {@code text} lists no variant: {@code none}, or nothing but separators and blanks. */
    public static boolean namesNone(String text) {
        return text.strip().equals(NONE) || split(text).stream().allMatch(String::isBlank);
    }

    /** Splits at ';' outside quotes: a program's arguments may quote one. */
    private static List<String> split(String text) {
        List<String> parts = new ArrayList<>();
        StringBuilder part = new StringBuilder();
        char quote = 0;
        for (char c : text.toCharArray()) {
            if (quote == 0 && c == ';') {
                parts.add(part.toString());
                part.setLength(0);
                continue;
            }
            if (quote == 0 && (c == '\'' || c == '"')) {
                quote = c;
            } else if (c == quote) {
                quote = 0;
            }
            part.append(c);
        }
        parts.add(part.toString());
        return parts;
    }

    /** The list as {@link #parse} reads it. */
    public static String format(List<Variant> variants) {
        if (variants.isEmpty()) {
            return NONE;
        }
        return String.join(";", variants.stream().map(Variant::spec).toList());
    }

    /** The one seeded fault {@code spec} names ({@code builtin:F}), or null when it names something else. */
    private static Fault seeded(String spec) {
        if (!spec.startsWith("builtin:")) {
            return null;
        }
        Set<Fault> faults = FaultSet.parse(spec.substring("builtin:".length()));
        if (faults.isEmpty()) {
            throw new IllegalArgumentException("builtin: needs the faults to plant, e.g. builtin:16 or builtin:16,17");
        }
        return faults.size() == 1 ? faults.iterator().next() : null;
    }
}
