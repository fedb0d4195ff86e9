package sitcov.judge;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import sitcov.faults.Fault;
import sitcov.seam.SeamFault;

/**
 * A version of the reference controller that an experiment judges against it by the differential
 * oracle (experiments/controllers/README.md, "Variants: versions of your controller, judged against
 * it"): one of the builtin car's seeded faults switched on in the reference, a seam fault (a sensor
 * or actuator fault between the reference and the world), or another controller altogether (a
 * program, an in-process controller, the builtin car with faults planted). Every result names it
 * by its {@link #id()} and {@link #label()}; a seeded fault
 * keeps its catalogue id and label, so folders of the builtin car read as they always did.
 */
public sealed interface Variant {
    /** Its number in every result: a seeded fault's catalogue id, or the next free one. */
    int id();

    /** A short name without spaces or commas, as results and figures print it. */
    String label();

    /** The variant as a preset writes it, e.g. {@code builtin:17} or {@code exec:python3 mine.py --bug}. */
    String spec();

    /**
     * A seeded fault of the builtin car, switched on in the reference run: the run is the reference's
     * until the fault first departs from it, so it can be forked there.
     */
    record Seeded(Fault fault) implements Variant {
        @Override
        public int id() {
            return fault.id();
        }

        @Override
        public String label() {
            return fault.label();
        }

        @Override
        public String spec() {
            return "builtin:" + fault.id();
        }
    }

    /**
     * A seam fault of the reference: the reference's controller with the fault between it and the world.
     * Its run is the reference's until the fault first changes a value, so it can be forked there when the
     * reference's controller can be copied. Its label is its spec, {@code seam:NAME}.
     */
    record Seam(int id, SeamFault fault) implements Variant {
        @Override
        public String label() {
            return fault.spec();
        }

        @Override
        public String spec() {
            return fault.spec();
        }
    }

    /** Another controller: its runs are its own from the first tick, run whole. */
    record Controller(int id, String label, String spec) implements Variant {
        public Controller {
            if (label.isEmpty() || label.chars().anyMatch(c -> c == ',' || Character.isWhitespace(c))) {
                throw new IllegalArgumentException("a variant's label has no spaces or commas: '" + label + "'");
            }
        }
    }

    /** The seeded faults of {@code variants}, in their order. */
    static List<Fault> faultsOf(List<? extends Variant> variants) {
        List<Fault> faults = new ArrayList<>();
        for (Variant v : variants) {
            if (v instanceof Seeded s) {
                faults.add(s.fault());
            }
        }
        return faults;
    }

    /** The seam faults of {@code variants}, in their order. */
    static List<SeamFault> seamsOf(List<? extends Variant> variants) {
        List<SeamFault> seams = new ArrayList<>();
        for (Variant v : variants) {
            if (v instanceof Seam s) {
                seams.add(s.fault());
            }
        }
        return seams;
    }

    /**
     * Numbers a list of variants given by their specs: a seeded fault ({@code builtin:F} with one fault)
     * keeps its id, every other variant (a seam fault {@code seam:NAME} among them) takes the smallest id
     * from 1 up that nothing before it took.
     * {@code seeded} tells which specs name one seeded fault of the reference (null for the others).
     */
    static List<Variant> number(List<String> specs, java.util.function.Function<String, Fault> seeded) {
        Set<Integer> taken = new HashSet<>();
        List<Fault> faults = new ArrayList<>();
        for (String spec : specs) {
            Fault f = seeded.apply(spec);
            faults.add(f);
            if (f != null && !taken.add(f.id())) {
                throw new IllegalArgumentException("fault " + f.id() + " is listed twice among the variants");
            }
        }
        List<Variant> variants = new ArrayList<>(specs.size());
        Set<String> labels = new HashSet<>();
        int next = 1;
        for (int i = 0; i < specs.size(); i++) {
            Variant v;
            if (faults.get(i) != null) {
                v = new Seeded(faults.get(i));
            } else {
                while (taken.contains(next)) {
                    next++;
                }
                taken.add(next);
                v = SeamFault.names(specs.get(i)) ? new Seam(next, SeamFault.parse(specs.get(i)).get(0))
                        : new Controller(next, labelOf(specs.get(i)), specs.get(i).strip());
            }
            if (!labels.add(v.label())) {
                if (v instanceof Seam) {
                    throw new IllegalArgumentException(v.spec() + " is listed twice among the variants");
                }
                v = v instanceof Controller c ? new Controller(c.id(), c.label() + "-" + c.id(), c.spec()) : v;
                labels.add(v.label());
            }
            variants.add(v);
        }
        return List.copyOf(variants);
    }

    /**
     * A label from a spec: what tells the controller apart, in one word — for a program its file's
     * name and its arguments ({@code exec:python3 dir/mine.py --bug late} gives {@code mine.py-bug-late}),
     * for an in-process controller its name.
     */
    static String labelOf(String spec) {
        String s = spec.strip();
        int colon = s.indexOf(':');
        String body = colon < 0 ? s : s.substring(colon + 1).strip();
        if (s.startsWith("exec:")) {
            String[] words = body.split("\\s+");
            int first = 0;
            // an interpreter's name says less than the script it runs
            while (first < words.length - 1 && !words[first].contains("/") && !words[first].contains(".")
                    && !words[first].startsWith("-")) {
                first++;
            }
            StringBuilder b = new StringBuilder();
            for (int w = first; w < words.length; w++) {
                String word = words[w];
                if (w == first) {
                    word = word.substring(word.lastIndexOf('/') + 1);
                }
                b.append(b.length() == 0 ? "" : "-").append(word);
            }
            body = b.toString();
        } else if (s.startsWith("builtin:")) {
            body = "builtin-" + body;
        }
        String label = body.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9._]+", "-").replaceAll("^-+|-+$", "");
        return label.isEmpty() ? "variant" : label;
    }
}
