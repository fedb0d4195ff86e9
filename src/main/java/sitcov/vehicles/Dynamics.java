package sitcov.vehicles;

/** Speeds and turns every car shares (faults/README.md, "The car under test, the traffic and the oracle"), per tick of 0.2 s. */
public final class Dynamics {
    /** 2.5 m per tick: 12.5 m/s, 45 km/h. */
    public static final double MAX_SPEED = 2.5;
    public static final double ACCELERATION = 0.1;
    public static final double BRAKING = 0.15625;
    public static final double MAX_TURN = 15;
    /** The crawl band: below its floor a crawling car accelerates, at or above its ceiling it brakes. */
    public static final double CRAWL_FLOOR = BRAKING;
    public static final double CRAWL_CEILING = 2 * BRAKING;
    /** Ticks in a run before it times out. */
    public static final long TIMEOUT_TICKS = 5000;

    private static final double FULL_SPEED_STOPPING_DISTANCE = stoppingDistance(MAX_SPEED);
    /** Stopping distances of speeds 0, 1 mm, 2 mm … a tick, up to full speed: inverted by bisection. */
    private static final double SPEED_STEP = 0.001;
    private static final double[] STOPPING = tabulateStopping();
    private static final SortedLookup STOPPING_LOOKUP = sortedOrFail(STOPPING);

    private static double[] tabulateStopping() {
        double[] table = new double[(int) Math.round(MAX_SPEED / SPEED_STEP) + 1];
        for (int i = 0; i < table.length; i++) {
            table[i] = stoppingDistance(i * SPEED_STEP);
        }
        return table;
    }

    private static SortedLookup sortedOrFail(double[] table) {
        SortedLookup lookup = SortedLookup.of(table);
        if (lookup == null) {
            throw new IllegalStateException("stopping distances must grow with speed");
        }
        return lookup;
    }

    private Dynamics() {
    }

    /**
     * The distance a car plans to need to stop from {@code speed} (the original's rule): the current
     * speed counted once more than a braking car really travels — a tick of reaction — plus the
     * ticks of full braking: v + Σ (v − k·0.15625) over k = 0, 1, … while the term is positive.
     */
    public static double stoppingDistance(double speed) {
        if (speed <= 0) {
            return 0;
        }
        // n positive terms v, v − b, …, v − (n−1)·b: their sum in closed form
        long n = (long) Math.ceil(speed / BRAKING - 1e-12);
        return speed + n * speed - BRAKING * n * (n - 1) / 2.0;
    }

    /**
     * The highest speed from which a car can slow to {@code target} within {@code distance}: a tick
     * of reaction, then full braking.
     */
    public static double speedToSlowTo(double target, double distance) {
        if (distance <= 0 || target >= MAX_SPEED) {
            return Math.min(target, MAX_SPEED);
        }
        if (slowingDistance(MAX_SPEED, target) <= distance) {
            return MAX_SPEED;
        }
        return SlowingBisection.of(target).speedFor(distance);
    }

    /**
     * The bisection for {@link #speedToSlowTo}: slowing distance grows with the starting speed, so
     * bisect between the target and full speed to a millimetre a tick. The comparisons it makes
     * depend only on the target, so each target's tree of them is worked out once; following it
     * takes the same branches, and gives the same speed, as bisecting afresh.
     */
    private static final class SlowingBisection {
        /** Cars slow to a handful of speeds; a tree each, shared by every thread (immutable once made). */
        private static volatile SlowingBisection[] made = new SlowingBisection[0];

        private final double target;
        private int nodes;
        private double[] speed = new double[64];
        private double[] threshold = new double[64];
        private int[] fits = new int[64];
        private int[] tooFar = new int[64];
        /** The thresholds in order, when they never fall, and the leaves' speeds in order; else null. */
        private SortedLookup inOrder;
        private double[] leaves;

        private SlowingBisection(double target) {
            this.target = target;
            grow(target, MAX_SPEED);
            layOut();
        }

        static SlowingBisection of(double target) {
            SlowingBisection[] known = made;
            for (SlowingBisection tree : known) {
                if (tree.target == target) {
                    return tree;
                }
            }
            SlowingBisection tree = new SlowingBisection(target);
            synchronized (SlowingBisection.class) {
                SlowingBisection[] more = java.util.Arrays.copyOf(made, made.length + 1);
                more[more.length - 1] = tree;
                made = more;
            }
            return tree;
        }

        /** Node for the interval [lo, hi]: a leaf answering lo once the interval is a millimetre, else a comparison at its middle. */
        private int grow(double lo, double hi) {
            int node = nodes++;
            if (node == speed.length) {
                speed = java.util.Arrays.copyOf(speed, 2 * node);
                threshold = java.util.Arrays.copyOf(threshold, 2 * node);
                fits = java.util.Arrays.copyOf(fits, 2 * node);
                tooFar = java.util.Arrays.copyOf(tooFar, 2 * node);
            }
            if (!(hi - lo > 0.001)) {
                speed[node] = lo;
                fits[node] = -1;
                return node;
            }
            double mid = (lo + hi) / 2;
            threshold[node] = slowingDistance(mid, target);
            int whenFits = grow(mid, hi);
            int whenTooFar = grow(lo, mid);
            fits[node] = whenFits;
            tooFar[node] = whenTooFar;
            return node;
        }

        double speedFor(double distance) {
            if (inOrder != null) {
                return leaves[inOrder.countAtMost(distance)];
            }
            int node = 0;
            while (fits[node] >= 0) {
                node = threshold[node] <= distance ? fits[node] : tooFar[node];
            }
            return speed[node];
        }

        /**
         * Lays the tree out in order — leaf, threshold, leaf, … — for {@link #speedFor}. When the
         * thresholds never fall along that order (slowing distance grows with the starting speed), the
         * walk turns right exactly at the thresholds not above the distance, and ends at the leaf after
         * as many thresholds as that: a count a {@link SortedLookup} finds without the walk's chain of
         * unpredictable branches. Otherwise the tree is kept walking.
         */
        private void layOut() {
            double[] keys = new double[nodes / 2];
            double[] inOrderLeaves = new double[nodes / 2 + 1];
            int[] counts = new int[2];
            inOrder(0, keys, inOrderLeaves, counts);
            inOrder = SortedLookup.of(keys);
            leaves = inOrderLeaves;
        }

        private void inOrder(int node, double[] keys, double[] inOrderLeaves, int[] counts) {
            if (fits[node] < 0) {
                inOrderLeaves[counts[1]++] = speed[node];
                return;
            }
            inOrder(tooFar[node], keys, inOrderLeaves, counts);
            keys[counts[0]++] = threshold[node];
            inOrder(fits[node], keys, inOrderLeaves, counts);
        }
    }

    private static double slowingDistance(double from, double target) {
        double d = from;
        for (double v = from; v > target; v -= BRAKING) {
            d += v;
        }
        return d;
    }

    /** The highest speed from which a car can still stop within {@code distance}. */
    public static double speedToStopWithin(double distance) {
        if (distance <= 0) {
            return 0;
        }
        if (distance >= FULL_SPEED_STOPPING_DISTANCE) {
            return MAX_SPEED;
        }
        // the stopping distance grows with speed: the last tabulated speed that fits (the table starts at
        // 0, which fits; for NaN nothing does, and the search this replaced answered 0 too)
        int fitting = STOPPING_LOOKUP.countAtMost(distance);
        return fitting == 0 ? 0 : (fitting - 1) * SPEED_STEP;
    }
}
