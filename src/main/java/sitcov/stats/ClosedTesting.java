package sitcov.stats;

import java.util.Arrays;

/**
 * Holm's procedure over a family in which each place holds up to two hypotheses that cannot both be
 * true — a measure's "no difference" (δ = 0) and its "not equivalent" (|δ| ≥ margin). Closed testing
 * (Marcus, Peritz &amp; Gabriel 1976) rejects a hypothesis when every intersection holding it is
 * rejected by its local test; an intersection holding both hypotheses of one place is empty, so it is
 * rejected for free, and each place costs the family one test, not two (Goeman, Solari &amp; Stijnen
 * 2010, three-sided testing). With Bonferroni local tests the hardest intersection holding hypothesis h
 * of place j takes, from every other place, its hypothesis with the larger p: so h's adjusted p is its
 * Holm-adjusted p in the vector where place j holds h's p and every other place the larger of its two.
 * With one hypothesis per place this is Holm's procedure.
 */
public final class ClosedTesting {
    private ClosedTesting() {
    }

    /**
     * The adjusted p of every hypothesis: {@code p[j][k]} is hypothesis k of place j (NaN where a place
     * lacks it; a place with none is no place); the result has the same shape, NaN where p is.
     */
    public static double[][] adjust(double[][] p) {
        double[] larger = new double[p.length];
        int places = 0;
        for (int j = 0; j < p.length; j++) {
            larger[j] = Arrays.stream(p[j]).filter(v -> !Double.isNaN(v)).max().orElse(Double.NaN);
            places += Double.isNaN(larger[j]) ? 0 : 1;
        }
        double[][] adjusted = new double[p.length][];
        for (int j = 0; j < p.length; j++) {
            adjusted[j] = new double[p[j].length];
            for (int k = 0; k < p[j].length; k++) {
                adjusted[j][k] = Double.isNaN(p[j][k]) ? Double.NaN : holmAt(larger, j, p[j][k], places);
            }
        }
        return adjusted;
    }

    /** Holm's adjusted p of place j when it holds {@code value} and every other place its larger p. */
    private static double holmAt(double[] larger, int j, double value, int places) {
        double[] q = new double[places];
        int at = -1;
        int n = 0;
        for (int i = 0; i < larger.length; i++) {
            if (i == j) {
                at = n;
                q[n++] = value;
            } else if (!Double.isNaN(larger[i])) {
                q[n++] = larger[i];
            }
        }
        return Holm.adjust(q)[at];
    }
}
