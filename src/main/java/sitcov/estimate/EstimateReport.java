package sitcov.estimate;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The estimates an estimate's samples give, per requirement and method (estimate.csv), and what
 * they say in sentences (estimate.txt): each rate with its interval, whether the two methods
 * agree, and how many ticks importance sampling needed against plain Monte Carlo at equal precision.
 */
public final class EstimateReport {
    private final EstimateConfig config;
    private final List<Estimate> estimates = new ArrayList<>();
    private final long ceTicks;
    private final int ceRuns;

    public EstimateReport(EstimateConfig config, List<Sample> samples) {
        this.config = config;
        List<Sample> mc = samples.stream().filter(s -> s.stage().equals("mc")).toList();
        List<Sample> ce = samples.stream().filter(s -> s.stage().startsWith("ce-")).toList();
        ceTicks = ce.stream().mapToLong(Sample::ticks).sum();
        ceRuns = ce.size();
        // the cross-entropy stages' runs are paid for and each stage's mean is unbiased: they count in the estimate
        List<Sample> is = samples.stream().filter(s -> s.stage().equals("is") || s.stage().startsWith("ce-")).toList();
        boolean drawn = samples.stream().anyMatch(s -> s.stage().equals("is"));
        for (Failing r : Failing.all()) {
            if (!mc.isEmpty()) {
                estimates.add(Estimators.monteCarlo(mc, r));
            }
            if (drawn) {
                estimates.add(Estimators.importanceSampling(is, r));
            }
        }
    }

    public List<Estimate> estimates() {
        return estimates;
    }

    public static String csvHeader() {
        return "method,requirement,runs,ticks,failing_runs,rate,ci_low,ci_high,half_width,relative_half_width,ess";
    }

    public List<String> csvRows() {
        return estimates.stream().map(e -> String.format(Locale.ROOT, "%s,%s,%d,%d,%d,%.8f,%.8f,%.8f,%.8f,%s,%.1f",
                e.method(), e.requirement().column(), e.runs(), e.ticks(), e.failing(), e.rate(), e.low(), e.high(),
                e.halfWidth(), Double.isFinite(e.relativeHalfWidth())
                        ? String.format(Locale.ROOT, "%.4f", e.relativeHalfWidth()) : "", e.ess())).toList();
    }

    /** The estimate of {@code method} for {@code requirement}, or null. */
    public Estimate of(String method, String requirement) {
        return estimates.stream().filter(e -> e.method().equals(method) && e.requirement().column().equals(requirement))
                .findFirst().orElse(null);
    }

    /**
     * How many times the ticks importance sampling needs at the relative half-width plain Monte Carlo
     * needs: ticks scale as 1 / half-width², so each method's ticks are brought to one precision.
     */
    public static double ticksRatio(Estimate mc, Estimate is) {
        return mc.ticks() * sq(mc.relativeHalfWidth()) / (is.ticks() * sq(is.relativeHalfWidth()));
    }

    public static double runsRatio(Estimate mc, Estimate is) {
        return mc.runs() * sq(mc.relativeHalfWidth()) / (is.runs() * sq(is.relativeHalfWidth()));
    }

    /** Whether two estimates of one rate agree: their difference within 1.96 of its standard error. */
    public static boolean agree(Estimate a, Estimate b) {
        return Math.abs(a.rate() - b.rate()) <= Estimators.Z95 * Math.hypot(a.standardError(), b.standardError());
    }

    public List<String> text() {
        List<String> t = new ArrayList<>();
        t.add("Failure rate of " + config.controller() + " on the generator's maps (" + config.name() + ", master seed "
                + config.masterSeed() + ", " + config.replications() + " replication" + (config.replications() == 1 ? "" : "s") + ")");
        t.add("");
        Estimate mcAny = of("mc", "any");
        Estimate isAny = of("is", "any");
        if (mcAny != null) {
            t.add(String.format(Locale.ROOT, "Plain Monte Carlo: %d runs, %d ticks.", mcAny.runs(), mcAny.ticks()));
        }
        if (isAny != null) {
            t.add(String.format(Locale.ROOT, "Importance sampling: %d runs, %d ticks (%d runs and %d ticks of them in"
                    + " %d cross-entropy stages, counted in the estimate); effective sample size %.1f of %d runs.",
                    isAny.runs(), isAny.ticks(), ceRuns, ceTicks, config.ceStages(), isAny.ess(), isAny.runs()));
        }
        t.add("");
        t.add(String.format(Locale.ROOT, "%-20s %-38s %-38s %s", "requirement", "plain Monte Carlo [95% CI] (failing)",
                "importance sampling [95% CI] (failing)", mcAny != null && isAny != null ? "agree" : ""));
        for (Failing r : Failing.all()) {
            Estimate mc = of("mc", r.column());
            Estimate is = of("is", r.column());
            t.add(String.format(Locale.ROOT, "%-20s %-38s %-38s %s", r.column(), shown(mc), shown(is),
                    mc != null && is != null ? (agree(mc, is) ? "yes" : "NO") : "").stripTrailing());
        }
        if (mcAny != null && isAny != null) {
            t.add("");
            t.add(closing(mcAny, isAny));
        }
        return t;
    }

    private static String closing(Estimate mc, Estimate is) {
        if (mc.failing() == 0 || is.failing() == 0) {
            return "No precision to compare: " + (mc.failing() == 0 ? "plain Monte Carlo" : "importance sampling")
                    + " saw no failure.";
        }
        return String.format(Locale.ROOT, "Any failure: plain Monte Carlo %.3f%% ± %.1f%% (relative), importance sampling"
                        + " %.3f%% ± %.1f%%; the two %s. At equal relative half-width importance sampling needs %s ticks"
                        + " (%s runs) than plain Monte Carlo, its cross-entropy stages included.",
                100 * mc.rate(), 100 * mc.relativeHalfWidth(), 100 * is.rate(), 100 * is.relativeHalfWidth(),
                agree(mc, is) ? "agree within their intervals" : "DISAGREE", times(ticksRatio(mc, is)), times(runsRatio(mc, is)));
    }

    /** A ratio of plain Monte Carlo's cost to importance sampling's, in words. */
    private static String times(double ratio) {
        return ratio >= 1 ? String.format(Locale.ROOT, "%.2fx fewer", ratio)
                : String.format(Locale.ROOT, "%.2fx more", 1 / ratio);
    }

    private static String shown(Estimate e) {
        if (e == null) {
            return "-";
        }
        if (e.failing() == 0 && e.method().equals("is")) {
            return "0 (no failing run: no interval)";
        }
        return String.format(Locale.ROOT, "%.3f%% [%.3f, %.3f] (%d)", 100 * e.rate(), 100 * e.low(), 100 * e.high(),
                e.failing());
    }

    private static double sq(double x) {
        return x * x;
    }
}
