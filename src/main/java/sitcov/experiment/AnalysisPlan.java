package sitcov.experiment;

import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;

/**
 * How a comparison's results are judged, declared before they exist: the one primary question
 * (which measure, which two drivers, which direction), tested at {@link #ALPHA} as it stands, and the
 * equivalence margin of every measure. Everything else a results folder tests is exploratory: the
 * measures one family under closed testing, the faults a screening family under Benjamini–Hochberg
 * ({@code sitcov.analysis.Comparison}). The defaults: distinct faults found, the first driver against the
 * second, two-sided, and each measure's {@link Measure#defaultMargin()}. Presets and manifests hold
 * it under the keys {@link #keys()} names.
 */
public record AnalysisPlan(Measure primaryMeasure, List<String> primaryDrivers, Direction primaryDirection,
                           Map<Measure, Double> margins) {
    /** The level of every test and of the family as a whole. */
    public static final double ALPHA = 0.05;
    public static final String PRIMARY_MEASURE = "primary_measure";
    public static final String PRIMARY_DRIVERS = "primary_drivers";
    public static final String PRIMARY_DIRECTION = "primary_direction";
    public static final String MARGIN = "margin_";

    public AnalysisPlan {
        primaryDrivers = List.copyOf(primaryDrivers);
        if (primaryDrivers.size() == 2 && primaryDrivers.get(0).equals(primaryDrivers.get(1))
                || primaryDrivers.size() > 2 || primaryDrivers.size() == 1) {
            throw new IllegalArgumentException("primary_drivers names two different drivers, got " + primaryDrivers);
        }
        EnumMap<Measure, Double> all = new EnumMap<>(Measure.class);
        for (Measure m : Measure.values()) {
            double v = margins.getOrDefault(m, m.defaultMargin());
            if (!(v > 0) || Double.isInfinite(v)) {
                throw new IllegalArgumentException(MARGIN + m.key() + " must be a positive number, got " + v);
            }
            all.put(m, v);
        }
        margins = java.util.Collections.unmodifiableMap(all);
    }

    /** The defaults for a comparison of {@code drivers}: the first against the second (no primary with one driver). */
    public static AnalysisPlan defaults(List<String> drivers) {
        List<String> distinct = drivers.stream().distinct().toList();
        return new AnalysisPlan(Measure.FAULTS_FOUND, distinct.size() < 2 ? List.of() : distinct.subList(0, 2),
                Direction.TWO_SIDED, Map.of());
    }

    /**
     * The plan a preset or manifest declares, read through {@code property} (null where a key is
     * absent: its default); {@code drivers} are the experiment's.
     *
     * @throws IllegalArgumentException naming the key and the fix
     */
    public static AnalysisPlan read(Function<String, String> property, List<String> drivers) {
        AnalysisPlan defaults = defaults(drivers);
        String measure = property.apply(PRIMARY_MEASURE);
        String named = property.apply(PRIMARY_DRIVERS);
        String direction = property.apply(PRIMARY_DIRECTION);
        List<String> pair = named == null ? defaults.primaryDrivers()
                : java.util.Arrays.stream(named.split(",")).map(String::strip).toList();
        for (String d : pair) {
            if (!drivers.contains(d)) {
                throw new IllegalArgumentException(PRIMARY_DRIVERS + "= names '" + d + "', which is not one of the drivers "
                        + drivers);
            }
        }
        Map<Measure, Double> margins = new EnumMap<>(Measure.class);
        for (Measure m : Measure.values()) {
            String v = property.apply(MARGIN + m.key());
            if (v != null) {
                try {
                    margins.put(m, Double.parseDouble(v.strip()));
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException(MARGIN + m.key() + "= needs a positive number such as "
                            + m.defaultMargin() + ", not '" + v.strip() + "'");
                }
            }
        }
        try {
            return new AnalysisPlan(measure == null ? defaults.primaryMeasure() : Measure.ofKey(measure.strip()), pair,
                    direction == null ? defaults.primaryDirection() : Direction.ofKey(direction.strip()), margins);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(e.getMessage().startsWith("unknown measure")
                    ? PRIMARY_MEASURE + "= " + e.getMessage() : e.getMessage(), e);
        }
    }

    /** Every key a preset may give, for its list of known keys. */
    public static List<String> keys() {
        List<String> keys = new java.util.ArrayList<>(List.of(PRIMARY_MEASURE, PRIMARY_DRIVERS, PRIMARY_DIRECTION));
        for (Measure m : Measure.values()) {
            keys.add(MARGIN + m.key());
        }
        return keys;
    }

    /**
     * The measures compared, in order: the paper's, and the reference's own failures too when the primary
     * question is about them (a preset with no variants asks it by default).
     */
    public List<Measure> measures() {
        if (!primaryMeasure.ofOwnFailures()) {
            return Measure.PAPER;
        }
        List<Measure> all = new java.util.ArrayList<>(Measure.PAPER);
        all.add(Measure.OWN_FAILURES);
        all.add(Measure.DISTINCT_OWN_FAILURES);
        return List.copyOf(all);
    }

    /** The same plan with {@code measure} as the primary question's. */
    public AnalysisPlan withPrimary(Measure measure) {
        return new AnalysisPlan(measure, primaryDrivers, primaryDirection, margins);
    }

    /** The plan as key=value pairs, as a manifest records it. */
    public Map<String, String> properties() {
        Map<String, String> p = new LinkedHashMap<>();
        p.put(PRIMARY_MEASURE, primaryMeasure.key());
        if (hasPrimary()) {
            p.put(PRIMARY_DRIVERS, String.join(",", primaryDrivers));
        }
        p.put(PRIMARY_DIRECTION, primaryDirection.key());
        List<Measure> compared = measures();
        margins.forEach((m, v) -> {
            if (compared.contains(m)) {
                p.put(MARGIN + m.key(), format(v));
            }
        });
        return p;
    }

    public boolean hasPrimary() {
        return primaryDrivers.size() == 2;
    }

    public double margin(Measure m) {
        return margins.get(m);
    }

    /** Whether the pair (a, b) is the primary question's, in either order, on {@code measure}. */
    public boolean isPrimary(Measure measure, String a, String b) {
        return hasPrimary() && measure == primaryMeasure && (primaryDrivers.equals(List.of(a, b))
                || primaryDrivers.equals(List.of(b, a)));
    }

    private static String format(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : String.format(Locale.ROOT, "%s", v);
    }
}
