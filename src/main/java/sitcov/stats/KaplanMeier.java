package sitcov.stats;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.OptionalDouble;

/**
 * The Kaplan–Meier estimate of a survival curve from times that either end in the event (a
 * campaign's first failure) or are censored (a trial whose budget ran out first). At each distinct
 * event time t the curve drops by the factor 1 − d/n, d the events at t and n the trials still at
 * risk just before t; a censored time leaves the risk set after the events at the same time.
 *
 * <p>The median's interval is Brookmeyer and Crowley's (1982, "A confidence interval for the median
 * survival time", Biometrics 38:29): the times t at which the test of S(t) = ½ is not rejected,
 * |Ŝ(t) − ½| ≤ z·se(t), with Greenwood's variance se(t)² = Ŝ(t)² Σ d/(n(n − d)) over the event times up to t.
 * Its ends are read off the curve as the median is: the lower end the first time Ŝ − z·se is ½ or below,
 * the upper end the first time Ŝ + z·se is; where every trial still at risk had the event, Ŝ is 0 and so
 * is se.
 */
public final class KaplanMeier {
    private KaplanMeier() {
    }

    /** One trial: when it ended, and whether it ended in the event (false: censored). */
    public record Observation(double time, boolean event) {
    }

    /** The curve just after an event time: how many were at risk, how many had the event, the survival. */
    public record Step(double time, int atRisk, int events, double survival) {
    }

    /** The curve's steps, one per distinct event time, in time order (empty when no trial had the event). */
    public static List<Step> curve(List<Observation> observations) {
        List<Observation> sorted = new ArrayList<>(observations);
        sorted.sort(Comparator.comparingDouble(Observation::time));
        List<Step> steps = new ArrayList<>();
        int atRisk = sorted.size();
        double survival = 1;
        int i = 0;
        while (i < sorted.size()) {
            double t = sorted.get(i).time();
            int events = 0;
            int leaving = 0;
            while (i < sorted.size() && sorted.get(i).time() == t) {
                if (sorted.get(i).event()) {
                    events++;
                }
                leaving++;
                i++;
            }
            if (events > 0) {
                survival *= 1 - (double) events / atRisk;
                steps.add(new Step(t, atRisk, events, survival));
            }
            atRisk -= leaving;
        }
        return steps;
    }

    /** The survival just after {@code time}: 1 before the first event. */
    public static double survivalAt(List<Step> curve, double time) {
        double s = 1;
        for (Step step : curve) {
            if (step.time() > time) {
                break;
            }
            s = step.survival();
        }
        return s;
    }

    /** The median's interval: each end empty where its band never falls to ½ (not reached). */
    public record MedianInterval(OptionalDouble low, OptionalDouble high) {
    }

    /** The Brookmeyer–Crowley interval of the median at normal deviate {@code z} (1.959964 for 95 %). */
    public static MedianInterval medianInterval(List<Step> curve, double z) {
        double greenwood = 0;
        OptionalDouble low = OptionalDouble.empty();
        OptionalDouble high = OptionalDouble.empty();
        for (Step step : curve) {
            int n = step.atRisk();
            int d = step.events();
            greenwood = n > d ? greenwood + (double) d / ((double) n * (n - d)) : Double.POSITIVE_INFINITY;
            double se = step.survival() == 0 ? 0 : step.survival() * Math.sqrt(greenwood);
            if (low.isEmpty() && step.survival() - z * se <= 0.5) {
                low = OptionalDouble.of(step.time());
            }
            if (high.isEmpty() && step.survival() + z * se <= 0.5) {
                high = OptionalDouble.of(step.time());
            }
        }
        return new MedianInterval(low, high);
    }

    /** The median time to the event: the first time the curve reaches 0.5 or below; empty if it never does. */
    public static OptionalDouble median(List<Step> curve) {
        for (Step step : curve) {
            if (step.survival() <= 0.5) {
                return OptionalDouble.of(step.time());
            }
        }
        return OptionalDouble.empty();
    }
}
