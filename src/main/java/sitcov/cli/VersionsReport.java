package sitcov.cli;

import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import sitcov.judge.VersionVerdict;
import sitcov.oracle.Accident;
import sitcov.stats.ConfidenceInterval;
import sitcov.stats.McNemar;
import sitcov.stats.Wilson;

/** The tables and words of a {@code versions} run: one CSV row per map and variant, a verdict per variant. */
final class VersionsReport {
    /** Maps listed by name in a variant's verdict, with the command that shows each. */
    static final int LISTED = 5;

    private VersionsReport() {
    }

    static String csv(VersionsPlan plan, List<List<VersionVerdict>> judged) {
        StringBuilder b = new StringBuilder("map_seed,internal_seed,variant,reference_outcome,reference_ticks,"
                + "reference_accidents,variant_outcome,variant_ticks,variant_accidents,new_accidents,fixed_accidents\n");
        for (List<VersionVerdict> map : judged) {
            for (VersionVerdict v : map) {
                b.append(v.run().externalSeed()).append(',').append(v.run().internalSeed()).append(',')
                        .append(v.variant() + 1).append(',')
                        .append(v.reference().outcome()).append(',').append(v.reference().ticks()).append(',')
                        .append(v.reference().accidents().size()).append(',')
                        .append(v.run().outcome()).append(',').append(v.run().ticks()).append(',')
                        .append(v.run().accidents().size()).append(',')
                        .append(list(v.fresh())).append(',').append(list(v.fixed())).append('\n');
            }
        }
        return b.toString();
    }

    private static String list(List<Accident> accidents) {
        return accidents.stream().map(a -> a.type() + "@" + a.tick()).collect(Collectors.joining(" "));
    }

    static String verdict(VersionsPlan plan, List<List<VersionVerdict>> judged) {
        int n = judged.size();
        StringBuilder b = new StringBuilder();
        b.append(String.format(Locale.ROOT, "Versions compared on %d maps (seeds %d to %d, each run with internal seed ="
                + " map seed)%nreference: %s%n", n, plan.firstSeed(), plan.firstSeed() + n - 1, plan.reference()));
        for (int v = 0; v < plan.variants().size(); v++) {
            int variant = v;
            List<VersionVerdict> mine = judged.stream().map(m -> m.get(variant)).toList();
            long regressed = mine.stream().filter(VersionVerdict::regressed).count();
            long improved = mine.stream().filter(VersionVerdict::improved).count();
            long worseOnly = mine.stream().filter(x -> x.regressed() && !x.improved()).count();
            long betterOnly = mine.stream().filter(x -> x.improved() && !x.regressed()).count();
            ConfidenceInterval ci = Wilson.interval(regressed, n);
            b.append(String.format(Locale.ROOT, "%nvariant %d: %s%n", v + 1, plan.variants().get(v)));
            b.append(String.format(Locale.ROOT, "  fails where the reference did not: %d of %d maps (%.1f %%, 95 %% CI"
                    + " %.1f–%.1f %%)%n", regressed, n, 100.0 * regressed / n, 100 * ci.low(), 100 * ci.high()));
            b.append(String.format(Locale.ROOT, "  the reference failed where it does not: %d of %d maps%n", improved, n));
            b.append(String.format(Locale.ROOT, "  paired (McNemar exact, maps only worse %d against only better %d):"
                    + " p = %s%n", worseOnly, betterOnly, p(McNemar.exactP(worseOnly, betterOnly))));
            mine.stream().filter(VersionVerdict::regressed).limit(LISTED).forEach(x -> {
                Accident a = x.fresh().get(0);
                b.append(String.format(Locale.ROOT, "    map %d: %s at t=%d (%.1f, %.1f), which the reference did not have%n",
                        x.run().externalSeed(), a.type(), a.tick(), a.x(), a.y()));
            });
        }
        b.append("\nA variant's accident is new when the reference's run of the same map and seeds has no accident of"
                + " its type within 10 m (the differential oracle). Runs: versions.csv.\n");
        return b.toString();
    }

    private static String p(double p) {
        return p < 0.001 ? "< 0.001" : String.format(Locale.ROOT, "%.3f", p);
    }
}
