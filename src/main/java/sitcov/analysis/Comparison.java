package sitcov.analysis;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.random.RandomGenerator;
import sitcov.experiment.AnalysisPlan;
import sitcov.experiment.Direction;
import sitcov.experiment.ExperimentConfig;
import sitcov.experiment.Measure;
import sitcov.experiment.ReplicationResult;
import sitcov.judge.Variant;
import sitcov.judge.Notion;
import sitcov.stats.Bootstrap;
import sitcov.stats.ConfidenceInterval;
import sitcov.stats.Descriptive;
import sitcov.stats.DetectableDifference;
import sitcov.stats.Dispersion;
import sitcov.stats.FisherExact;
import sitcov.stats.BenjaminiHochberg;
import sitcov.stats.ClosedTesting;
import sitcov.stats.MannWhitney;
import sitcov.stats.Tost;
import sitcov.stats.VarghaDelaney;
import sitcov.stats.WilcoxonSignedRank.Alternative;
import sitcov.stats.WilcoxonSignedRank;

/**
 * Whether one driver beats another, with no more claimed than the data show. Every pair of drivers
 * (earlier against later in the preset) is compared replication by replication ({@link
 * PairedReplications}: the replication is the unit, as a driver's maps within one are not
 * independent):
 * <ul>
 * <li>per measure, the paired difference with its bootstrap CI and signed-rank p, and Schuirmann's
 * two one-sided t-tests against the measure's equivalence margin;</li>
 * <li>per fault, each replication's share of maps finding it, paired the same way; the maps of all
 * replications pooled (Fisher's exact test, the odds ratio) only as description, beside the
 * dispersion that shows how far pooling overstates the evidence.</li>
 * </ul>
 * The one primary question the {@link AnalysisPlan} declares is tested at {@link AnalysisPlan#ALPHA}
 * as it stands (its difference and equivalence tests together, as three-sided testing allows:
 * Goeman, Solari &amp; Stijnen 2010, Statistics in Medicine 29:2117). Every other test is exploratory,
 * in one of two families ({@link Families}): the measures of every pair, each measure's difference and
 * equivalence tests together by closed testing ({@link ClosedTesting}: family-wise error 5 %); and the
 * faults of every pair, a screening family under Benjamini–Hochberg (false-discovery rate 5 %). Tests
 * that cannot find anything stay out of the families: a measure constant in every replication of both
 * drivers or identical to an earlier measure, a fault found by neither driver or on every map by both,
 * and a difference test whose smallest attainable p is not below the level (too few replications
 * differ; Tarone 1990's argument, and Gilbert 2005's for false-discovery rates).
 */
public final class Comparison {
    private static final double POWER = 0.8;
    /** The note of every test of a folder that holds no replication (a shard of more shards than replications). */
    static final String NO_REPLICATIONS = "there are no replications to compare";

    private final AnalysisPlan plan;
    private final int replications;
    private final List<MeasureComparison> measures;
    private final List<FaultComparison> faults;
    private final Families families;

    private Comparison(AnalysisPlan plan, int replications, List<MeasureComparison> measures,
                       List<FaultComparison> faults, Families families) {
        this.plan = plan;
        this.replications = replications;
        this.measures = List.copyOf(measures);
        this.faults = List.copyOf(faults);
        this.families = families;
    }

    /** Every pair of drivers of {@code summary}, with bootstrap resamples drawn from {@code random}. */
    public static Comparison of(ExperimentConfig config, Summary summary, RandomGenerator random) {
        AnalysisPlan plan = config.analysis();
        List<MeasureComparison> measures = new ArrayList<>();
        List<FaultComparison> faults = new ArrayList<>();
        List<String> drivers = summary.drivers();
        for (int i = 0; i < drivers.size(); i++) {
            for (int j = i + 1; j < drivers.size(); j++) {
                PairedReplications pair = PairedReplications.of(summary, drivers.get(i), drivers.get(j), config.budget());
                measures(pair, plan, random, measures);
                faults(pair, summary.faults(), random, faults);
            }
        }
        return adjust(plan, summary.results().size(), measures, faults);
    }

    public AnalysisPlan plan() {
        return plan;
    }

    public int replications() {
        return replications;
    }

    public List<MeasureComparison> measures() {
        return measures;
    }

    public List<FaultComparison> faults() {
        return faults;
    }

    /** The primary question's test, if the plan has one. */
    public java.util.Optional<MeasureComparison> primary() {
        return measures.stream().filter(MeasureComparison::primary).findFirst();
    }

    /** The exploratory families' sizes: the measures' places and tests, the faults' screening tests. */
    public Families families() {
        return families;
    }

    private static void measures(PairedReplications pair, AnalysisPlan plan, RandomGenerator random,
            List<MeasureComparison> out) {
        List<double[][]> earlier = new ArrayList<>();
        List<Measure> compared = plan.measures();
        for (Measure m : compared) {
            double[] x = pair.measureA(m);
            double[] y = pair.measureB(m);
            boolean primary = plan.isPrimary(m, pair.a(), pair.b());
            Alternative alternative = primary ? plan.primaryDirection().alternative(plan.primaryDrivers().get(0)
                    .equals(pair.a())) : Alternative.TWO_SIDED;
            String note = notTestable(x, y, earlier, compared);
            earlier.add(new double[][] {x, y});
            PairedDifference paired = paired(x, y, alternative, random);
            double margin = plan.margin(m);
            Tost.Result tost = note == null && x.length >= 2
                    ? Tost.paired(x, y, margin, AnalysisPlan.ALPHA) : null;
            double a12 = VarghaDelaney.a12(x, y);
            out.add(new MeasureComparison(m, pair.a(), pair.b(), primary, paired, margin,
                    tost == null ? Double.NaN : tost.p(),
                    Double.NaN, tost == null ? Double.NaN : tost.low(), tost == null ? Double.NaN : tost.high(),
                    MannWhitney.test(x, y).p(), a12, VarghaDelaney.magnitude(a12), null, note));
        }
    }

    private static void faults(PairedReplications pair, List<Variant> list, RandomGenerator random,
            List<FaultComparison> out) {
        long mapsA = Arrays.stream(pair.mapsA()).sum();
        long mapsB = Arrays.stream(pair.mapsB()).sum();
        for (int f = 0; f < list.size(); f++) {
            long foundA = Arrays.stream(pair.foundA(f)).sum();
            long foundB = Arrays.stream(pair.foundB(f)).sum();
            String note = pair.mapsA().length == 0 ? NO_REPLICATIONS : foundA + foundB == 0 ? "found by neither driver"
                    : foundA == mapsA && foundB == mapsB ? "found on every map by both" : null;
            PairedDifference paired = paired(pair.shareA(f), pair.shareB(f), Alternative.TWO_SIDED, random);
            FisherExact.Result fisher = note == null ? FisherExact.test(foundA, mapsA - foundA, foundB, mapsB - foundB) : null;
            out.add(new FaultComparison(list.get(f), pair.a(), pair.b(), paired,
                    Dispersion.pearson(pair.foundA(f), pair.mapsA()),
                    Dispersion.pearson(pair.foundB(f), pair.mapsB()), foundA, mapsA, foundB, mapsB,
                    fisher == null ? Double.NaN : fisher.p(), fisher == null ? Double.NaN : fisher.oddsRatio(),
                    fisher == null ? Double.NaN : fisher.low(), fisher == null ? Double.NaN : fisher.high(), null, note));
        }
    }

    private static PairedDifference paired(double[] x, double[] y, Alternative alternative, RandomGenerator random) {
        double[] d = differences(x, y);
        int differing = (int) Arrays.stream(d).filter(v -> v != 0).count();
        int higherA = (int) Arrays.stream(d).filter(v -> v > 0).count();
        WilcoxonSignedRank.Result w = WilcoxonSignedRank.test(d, alternative);
        int lean = (int) Math.signum(w.wPlus() - w.n() * (w.n() + 1) / 4.0);
        double spread = d.length < 2 ? Double.NaN : Math.sqrt(Descriptive.variance(d));
        return new PairedDifference(x.length, Descriptive.mean(x), Descriptive.mean(y),
                Bootstrap.pairedMeanDifference(x, y, random), spread, differing, higherA, lean, w.p(),
                WilcoxonSignedRank.smallestP(d, alternative), Double.NaN, Double.NaN);
    }

    /**
     * Why a measure cannot be tested for this pair, or null: no replications (an empty shard), constant in
     * both, or the numbers of an earlier measure.
     */
    private static String notTestable(double[] x, double[] y, List<double[][]> earlier, List<Measure> compared) {
        if (x.length == 0) {
            return NO_REPLICATIONS;
        }
        boolean constant = Arrays.stream(x).allMatch(v -> v == x[0]) && Arrays.stream(y).allMatch(v -> v == x[0]);
        if (constant) {
            return "it is " + plain(x[0]) + " in every replication of both";
        }
        if (Arrays.equals(x, y)) {
            return "both drivers have the same value in every replication";
        }
        for (int e = 0; e < earlier.size(); e++) {
            if (Arrays.equals(earlier.get(e)[0], x) && Arrays.equals(earlier.get(e)[1], y)) {
                return "the same numbers as " + compared.get(e).words() + " for this pair";
            }
        }
        return null;
    }

    /**
     * The two exploratory families, then each test's finding. Measures: closed testing over every
     * measure of every pair, a measure's difference and equivalence tests taking one place ({@link
     * ClosedTesting}), so the chance of any false claim about a measure stays at 5 %. Faults: a screening
     * family under Benjamini–Hochberg, so that of the faults it flags at most 5 % are expected to be
     * false discoveries.
     */
    private static Comparison adjust(AnalysisPlan plan, int n, List<MeasureComparison> measures,
            List<FaultComparison> faults) {
        List<double[]> places = new ArrayList<>();
        int[] placeOf = new int[measures.size()];
        int differences = 0;
        int equivalences = 0;
        for (int i = 0; i < measures.size(); i++) {
            MeasureComparison m = measures.get(i);
            boolean exploratory = m.note() == null && !m.primary();
            double difference = exploratory && reachable(m.paired()) ? m.paired().p() : Double.NaN;
            double equivalence = exploratory ? m.pTost() : Double.NaN;
            differences += Double.isNaN(difference) ? 0 : 1;
            equivalences += Double.isNaN(equivalence) ? 0 : 1;
            placeOf[i] = Double.isNaN(difference) && Double.isNaN(equivalence) ? -1 : places.size();
            if (placeOf[i] >= 0) {
                places.add(new double[] {difference, equivalence});
            }
        }
        double[][] closed = ClosedTesting.adjust(places.toArray(double[][]::new));
        List<Double> p = new ArrayList<>();
        int[] faultAt = new int[faults.size()];
        for (int i = 0; i < faults.size(); i++) {
            FaultComparison f = faults.get(i);
            faultAt[i] = f.note() == null && reachable(f.paired()) ? p.size() : -1;
            if (faultAt[i] >= 0) {
                p.add(f.paired().p());
            }
        }
        double[] bh = BenjaminiHochberg.adjust(p.stream().mapToDouble(Double::doubleValue).toArray());
        int discoveries = (int) Arrays.stream(bh).filter(v -> v < AnalysisPlan.ALPHA).count();
        Families families = new Families(places.size(), differences, equivalences, p.size(), discoveries);
        List<MeasureComparison> judgedMeasures = new ArrayList<>();
        for (int i = 0; i < measures.size(); i++) {
            double[] adjusted = placeOf[i] < 0 ? new double[] {Double.NaN, Double.NaN} : closed[placeOf[i]];
            judgedMeasures.add(judge(measures.get(i), adjusted[0], adjusted[1], families.measureLevel(), plan));
        }
        List<FaultComparison> judgedFaults = new ArrayList<>();
        for (int i = 0; i < faults.size(); i++) {
            double q = faultAt[i] < 0 ? Double.NaN : bh[faultAt[i]];
            judgedFaults.add(judge(faults.get(i), q, families.faultLevel(q < AnalysisPlan.ALPHA)));
        }
        return new Comparison(plan, n, judgedMeasures, judgedFaults, families);
    }

    /** Whether the signed-rank test could reach the level at all on differences of these sizes. */
    private static boolean reachable(PairedDifference d) {
        return d.smallestP() < AnalysisPlan.ALPHA;
    }

    private static MeasureComparison judge(MeasureComparison m, double pAdjusted, double pTostAdjusted,
                                           double familyLevel, AnalysisPlan plan) {
        PairedDifference d = m.paired();
        boolean reachable = m.note() == null && reachable(d);
        double level = m.primary() ? AnalysisPlan.ALPHA : familyLevel;
        boolean twoSided = !m.primary() || plan.primaryDirection() == Direction.TWO_SIDED;
        double p = m.primary() ? d.p() : pAdjusted;
        double pTost = m.primary() ? m.pTost() : pTostAdjusted;
        PairedDifference judged = d.adjusted(reachable ? p : Double.NaN,
                reachable ? detectable(d, level, twoSided) : Double.NaN);
        Finding finding;
        String note = m.note();
        if (note != null) {
            finding = Finding.NOT_TESTABLE;
        } else if (reachable && p < AnalysisPlan.ALPHA && agrees(d)) {
            finding = d.lean() > 0 ? Finding.HIGHER_A : Finding.HIGHER_B;
        } else if (pTost < AnalysisPlan.ALPHA) {
            finding = Finding.EQUIVALENT;
        } else if (!reachable) {
            finding = Finding.TOO_FEW;
            note = tooFew(d);
        } else {
            finding = Finding.INCONCLUSIVE;
        }
        return new MeasureComparison(m.measure(), m.driverA(), m.driverB(), m.primary(), judged, m.margin(), m.pTost(),
                m.primary() ? m.pTost() : pTostAdjusted, m.tostLow(), m.tostHigh(), m.pMannWhitney(), m.a12(), m.effect(),
                finding, note);
    }

    private static FaultComparison judge(FaultComparison f, double pAdjusted, double level) {
        PairedDifference d = f.paired();
        boolean tested = !Double.isNaN(pAdjusted);
        Finding finding;
        String note = f.note();
        if (note != null) {
            finding = Finding.NOT_TESTABLE;
        } else if (!tested) {
            finding = Finding.TOO_FEW;
            note = tooFew(d);
        } else if (pAdjusted < AnalysisPlan.ALPHA && agrees(d)) {
            finding = d.lean() > 0 ? Finding.HIGHER_A : Finding.HIGHER_B;
        } else {
            finding = Finding.INCONCLUSIVE;
        }
        PairedDifference judged = d.adjusted(pAdjusted, tested ? detectable(d, level, true) : Double.NaN);
        return new FaultComparison(f.variant(), f.driverA(), f.driverB(), judged, f.dispersionA(), f.dispersionB(),
                f.foundA(), f.mapsA(), f.foundB(), f.mapsB(), f.pFisher(), f.oddsRatio(), f.oddsLow(), f.oddsHigh(),
                finding, note);
    }

    /**
     * A difference is claimed only where the signed ranks and the mean difference point the same way:
     * on skewed differences they can disagree, and then which driver is "higher" is not settled.
     */
    private static boolean agrees(PairedDifference d) {
        return d.lean() != 0 && Math.signum(d.difference().estimate()) == d.lean();
    }

    /** Why a difference was not tested: the smallest p its signed-rank test could give is in stats.csv. */
    private static String tooFew(PairedDifference d) {
        return tooFewReplications(d.replications()) || d.differing() == d.replications() ? "too few replications"
                : "only " + d.differing() + " of " + d.replications() + " replications differ";
    }

    /** Whether n paired replications are too few for any two-sided signed-rank test to reach the level: 2/2ⁿ ≥ α. */
    public static boolean tooFewReplications(int n) {
        return 2 / Math.pow(2, Math.max(0, n)) >= AnalysisPlan.ALPHA;
    }

    /**
     * The difference the test could have detected with 80 % power at {@code level}, from the paired
     * spread: infinite where even the most lopsided differences could not reach the level at this n,
     * NaN where there is no spread to estimate it from.
     */
    private static double detectable(PairedDifference d, double level, boolean twoSided) {
        if (d.smallestP() >= level) {
            return Double.POSITIVE_INFINITY;
        }
        return d.replications() < 2 || !(d.spread() > 0) ? Double.NaN
                : DetectableDifference.pairedT(d.spread(), d.replications(), level, twoSided, POWER);
    }

    private static double[] differences(double[] x, double[] y) {
        double[] d = new double[x.length];
        for (int i = 0; i < d.length; i++) {
            d[i] = x[i] - y[i];
        }
        return d;
    }

    /** A number as a person writes it: 5, 0.05, 0.125 (three significant digits at most, no trailing zeros). */
    public static String plain(double v) {
        return new java.math.BigDecimal(String.format(Locale.ROOT, "%.3g", v)).stripTrailingZeros().toPlainString();
    }

    /**
     * The measure of {@code driver} in every replication, in replication order, over everything it
     * ran (the area to the ticks the least spending driver of the replication spent), as the figures
     * show each driver beside all others.
     */
    public static double[] values(Summary summary, String driver, Measure measure) {
        List<ReplicationResult> results = summary.results();
        double[] v = new double[results.size()];
        for (int r = 0; r < v.length; r++) {
            ReplicationResult rep = results.get(r);
            Metrics m = summary.metrics(rep.replication(), driver, Notion.DIFFERENTIAL);
            v[r] = m.value(measure, Discovery.of(rep.of(driver), summary.faults()).area(
                    rep.drivers().stream().mapToLong(d -> d.spend().ticks()).min().orElse(0)));
        }
        return v;
    }
}
