package sitcov.sensors;

import java.util.List;
import sitcov.geom.Compass;
import sitcov.geom.Rays;
import sitcov.geom.Rect;
import sitcov.world.Axis;
import sitcov.world.Marking;
import sitcov.world.MarkingKind;
import sitcov.world.RoadNetwork;

/**
 * The road-marking camera: sampled rays fanned out from the car's front centre around the lane
 * direction, the left sector looking for the kerb-side edge line and the right sector for the
 * centre line. A ray reports the first sample that falls on a painted strip, and stops where it
 * leaves the road. Which samples hit is computed exactly from each ray's interval across each
 * strip, so the sampled semantics (and what coarser sampling misses) are kept without marching.
 * Reuses its buffers: one camera per car, not thread-safe.
 */
public final class MarkingCamera {
    private static final int MAX_CANDIDATES = 64;
    private static final int MAX_RAYS = 1024;
    /**
     * A line is taken to be the car's own when its hits lie within this much of the nearest one
     * seen, and no farther than {@link #FARTHEST_LINE} to the side: a ray that runs on along a
     * side road can see another road's lines, which must not be mistaken for the lane's.
     */
    static final double SAME_LINE = 0.3;
    static final double FARTHEST_LINE = 4.5;

    private RoadNetwork network;
    private Rect[] strips = new Rect[MAX_CANDIDATES];
    private double[] interval = new double[2];
    private double[] stripLo = new double[MAX_CANDIDATES];
    private double[] stripHi = new double[MAX_CANDIDATES];
    private double[] seen = new double[MAX_RAYS];
    /** Per ray of the fan in hand, its first marking hit (NaN: none), found strip by strip. */
    private double[] nearest = new double[MAX_RAYS];
    /** The last look with each of the (at most two: faulty and standard) settings; the one in hand. */
    private Look[] looks = new Look[2];
    private Look look;
    /** The look the car kept, for viewers. */
    private Look kept;
    private RoadReach roadReach;
    /** Four lanes, with the faulty and the standard settings. */
    private RayFan.Cache fans = new RayFan.Cache(16);

    public MarkingCamera(RoadNetwork network) {
        this.network = network;
        this.roadReach = new RoadReach(network);
    }

    /** Another camera on the same roads, with buffers and looks of its own. */
    public MarkingCamera another() {
        return new MarkingCamera(network);
    }

    /**
     * Looks from ({@code x}, {@code y}) around {@code lane} and estimates where the lane is. The
     * markings and the road never move, so a car standing where it stood at its last look with
     * these settings sees what it saw then, and is told so without looking again.
     */
    public LaneEstimate look(double x, double y, Compass lane, CameraSettings settings) {
        look = lookWith(settings);
        if (look.isFrom(x, y, lane)) {
            return look.estimate;
        }
        look.estimate = lookAfresh(x, y, lane, settings);
        look.x = x;
        look.y = y;
        look.lane = lane;
        return look.estimate;
    }

    private Look lookWith(CameraSettings settings) {
        for (int k = 0; k < looks.length; k++) {
            if (looks[k] == null) {
                looks[k] = new Look(settings);
                return looks[k];
            }
            if (looks[k].settings.equals(settings)) {
                return looks[k];
            }
        }
        // a third set of settings (never in a run, whose faults are fixed): forget the older look
        looks[1] = new Look(settings);
        return looks[1];
    }

    private LaneEstimate lookAfresh(double x, double y, Compass lane, CameraSettings settings) {
        double limit = settings.limit();
        look.hitCount = 0;
        roadReach.gather(x, y, limit);
        Compass right = lane.right();
        int n = nearbyStrips(x, y, lane, limit, MarkingKind.EDGE);
        int hits = 0;
        RayFan fan = fans.fan(RayFan.Form.STEPPING_RIGHT, lane.bearing(), settings.leftArc(), 0, settings.angularStep());
        boolean byStrip = nearestByStrip(x, y, fan, n, settings, limit);
        for (int ray = 0; ray < fan.size() && hits < MAX_RAYS; ray++) {
            double v = byStrip ? reported(x, y, fan, ray, right, nearest[ray])
                    : lateralOfHit(x, y, fan, ray, right, n, settings, limit);
            if (!Double.isNaN(v) && v < 0 && v > -FARTHEST_LINE) {
                seen[hits++] = v;
            }
        }
        double edge = nearestLine(hits);
        n = nearbyStrips(x, y, lane, limit, MarkingKind.CENTRE);
        hits = 0;
        fan = fans.fan(RayFan.Form.STEPPING_RIGHT, lane.bearing(), 0, -settings.rightArc(), settings.angularStep());
        byStrip = nearestByStrip(x, y, fan, n, settings, limit);
        for (int ray = 0; ray < fan.size() && hits < MAX_RAYS; ray++) {
            double v = byStrip ? reported(x, y, fan, ray, right, nearest[ray])
                    : lateralOfHit(x, y, fan, ray, right, n, settings, limit);
            if (!Double.isNaN(v) && v > 0 && v < FARTHEST_LINE) {
                seen[hits++] = v;
            }
        }
        double centre = nearestLine(hits);
        if (Double.isNaN(edge) && Double.isNaN(centre)) {
            return LaneEstimate.NOTHING_SEEN;
        }
        return new LaneEstimate(!Double.isNaN(edge), Double.isNaN(edge) ? 0 : edge,
                !Double.isNaN(centre), Double.isNaN(centre) ? 0 : centre);
    }

    /** Keeps the last look's marking hits as the ones a viewer is shown (the car's own look, not a comparison's). */
    public void keepHits() {
        kept = look;
    }

    public int keptHits() {
        return kept == null ? 0 : kept.hitCount;
    }

    public double keptX(int hit) {
        return kept.hitX[hit];
    }

    public double keptY(int hit) {
        return kept.hitY[hit];
    }

    /** The mean lateral offset of the hits on the line nearest the car (one side's hits are in {@code seen}); NaN if none. */
    private double nearestLine(int hits) {
        if (hits == 0) {
            return Double.NaN;
        }
        double nearest = Double.MAX_VALUE;
        for (int k = 0; k < hits; k++) {
            nearest = Math.min(nearest, Math.abs(seen[k]));
        }
        double sum = 0;
        int count = 0;
        for (int k = 0; k < hits; k++) {
            if (Math.abs(seen[k]) <= nearest + SAME_LINE) {
                sum += seen[k];
                count++;
            }
        }
        return sum / count;
    }

    /** The lateral offset (right positive) of the ray's first marking hit, or NaN. */
    private double lateralOfHit(double x, double y, RayFan fan, int ray, Compass right, int nStrips,
                                CameraSettings settings, double limit) {
        double slope = fan.slope(ray);
        double dx = fan.dx(ray);
        double dy = fan.dy(ray);
        double best = Double.NaN;
        for (int s = 0; s < nStrips; s++) {
            // a ray outside the slopes of a strip's corners cannot meet it (this only saves work; a ray
            // with no slope, square to the lane or behind, is always tried)
            if (!(slope < stripLo[s]) && !(slope > stripHi[s]) && strips[s].rayInterval(x, y, dx, dy, interval)) {
                double d = Rays.firstSample(interval[0], interval[1], settings.rangeStart(), settings.rangeStep(), limit);
                if (!Double.isNaN(d) && (Double.isNaN(best) || d < best)) {
                    best = d;
                }
            }
        }
        return reported(x, y, fan, ray, right, best);
    }

    /**
     * Each ray's first marking hit, as {@link #lateralOfHit} finds it, into {@link #nearest}, strip by
     * strip: a strip is tried only on the run of rays whose slopes its own span admits (the rays'
     * slopes fall along the fan), and on the rays with no slope, so the same ray–strip pairs are
     * tried as there, and each ray keeps the least hit — the same, in whatever order the strips come.
     * Saves trying every strip's span on every ray. False, with nothing done, for a fan whose slopes
     * do not fall, or one larger than the buffers: then {@link #lateralOfHit} is asked ray by ray.
     */
    private boolean nearestByStrip(double x, double y, RayFan fan, int nStrips, CameraSettings settings, double limit) {
        if (!fan.slopesFall() || fan.size() > MAX_RAYS) {
            return false;
        }
        java.util.Arrays.fill(nearest, 0, fan.size(), Double.NaN);
        for (int s = 0; s < nStrips; s++) {
            double lo = stripLo[s];
            double hi = stripHi[s];
            if (Double.isNaN(lo) || Double.isNaN(hi)) {
                // a NaN bound admits every ray on that side: try them as lateralOfHit would
                for (int ray = fan.slopedFrom(); ray < fan.slopedTo(); ray++) {
                    if (!(fan.slope(ray) < lo) && !(fan.slope(ray) > hi)) {
                        tryStrip(s, x, y, fan, ray, settings, limit);
                    }
                }
            } else {
                for (int ray = fan.firstSlopeAtMost(hi), last = fan.lastSlopeAtLeast(lo); ray <= last; ray++) {
                    tryStrip(s, x, y, fan, ray, settings, limit);
                }
            }
            for (int ray = 0; ray < fan.slopedFrom(); ray++) {
                tryStrip(s, x, y, fan, ray, settings, limit);
            }
            for (int ray = fan.slopedTo(); ray < fan.size(); ray++) {
                tryStrip(s, x, y, fan, ray, settings, limit);
            }
        }
        return true;
    }

    private void tryStrip(int s, double x, double y, RayFan fan, int ray, CameraSettings settings, double limit) {
        if (strips[s].rayInterval(x, y, fan.dx(ray), fan.dy(ray), interval)) {
            double d = Rays.firstSample(interval[0], interval[1], settings.rangeStart(), settings.rangeStep(), limit);
            if (!Double.isNaN(d) && (Double.isNaN(nearest[ray]) || d < nearest[ray])) {
                nearest[ray] = d;
            }
        }
    }

    /** The lateral offset of a ray's first marking hit {@code best} metres out (NaN: none), once the road is known to reach it; noted as a hit. */
    private double reported(double x, double y, RayFan fan, int ray, Compass right, double best) {
        double dx = fan.dx(ray);
        double dy = fan.dy(ray);
        // the ray stops where it leaves the road; only a ray that hit something needs to know where
        if (Double.isNaN(best) || !roadReach.reaches(x, y, dx, dy, best)) {
            return Double.NaN;
        }
        if (look.hitCount < MAX_RAYS) {
            look.hitX[look.hitCount] = x + best * dx;
            look.hitY[look.hitCount] = y + best * dy;
            look.hitCount++;
        }
        return best * (dx * right.dx() + dy * right.dy());
    }

    private int nearbyStrips(double x, double y, Compass lane, double limit, MarkingKind kind) {
        int n = 0;
        // the camera follows lines that run along the lane; across-lines belong to other roads
        List<Marking> along = network.markings(kind, Axis.of(lane));
        for (int each = 0, count = along.size(); each < count; each++) {
            Rect strip = along.get(each).strip();
            if (n < MAX_CANDIDATES && near(strip, x, y, limit)) {
                slopesOf(n, strip, x, y, lane);
                strips[n++] = strip;
            }
        }
        return n;
    }

    /**
     * The span of ray slopes (left over ahead, in the lane's frame) that can meet strip {@code k},
     * a little wider than exact: it only spares rays that cannot meet the strip the exact test.
     * A ray from the car meets a strip only ahead of the car, where the slopes of the strip's
     * points lie between those of its corners ahead; a strip reaching back beside or behind the
     * car opens the span on that side.
     */
    private void slopesOf(int k, Rect strip, double x, double y, Compass lane) {
        if (strip.contains(x, y)) {
            stripLo[k] = Double.NEGATIVE_INFINITY;
            stripHi[k] = Double.POSITIVE_INFINITY;
            return;
        }
        Compass right = lane.right();
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        boolean back = false;
        boolean anyLeft = false;
        boolean anyRight = false;
        for (int corner = 0; corner < 4; corner++) {
            double ex = ((corner & 1) == 0 ? strip.minX() : strip.maxX()) - x;
            double ey = ((corner & 2) == 0 ? strip.minY() : strip.maxY()) - y;
            double ahead = ex * lane.dx() + ey * lane.dy();
            double left = -(ex * right.dx() + ey * right.dy());
            anyLeft |= left >= 0;
            anyRight |= left <= 0;
            if (ahead > 0) {
                lo = Math.min(lo, left / ahead);
                hi = Math.max(hi, left / ahead);
            } else {
                back = true;
            }
        }
        if (lo > hi) {
            // wholly beside or behind the car: no ray ahead meets it
            stripLo[k] = Double.POSITIVE_INFINITY;
            stripHi[k] = Double.NEGATIVE_INFINITY;
            return;
        }
        if (back) {
            lo = anyRight ? Double.NEGATIVE_INFINITY : lo;
            hi = anyLeft ? Double.POSITIVE_INFINITY : hi;
        }
        stripLo[k] = lo - 1e-9 * (1 + Math.abs(lo));
        stripHi[k] = hi + 1e-9 * (1 + Math.abs(hi));
    }

    private static boolean near(Rect r, double x, double y, double limit) {
        return r.minX() <= x + limit && r.maxX() >= x - limit && r.minY() <= y + limit && r.maxY() >= y - limit;
    }

    /** A look with one camera's settings: where it was taken from, what it estimated, where its rays met a marking. */
    private static final class Look {
        private CameraSettings settings;
        private double[] hitX = new double[MAX_RAYS];
        private double[] hitY = new double[MAX_RAYS];
        private int hitCount;
        private double x = Double.NaN;
        private double y = Double.NaN;
        private Compass lane;
        private LaneEstimate estimate;

        private Look(CameraSettings settings) {
            this.settings = settings;
        }

        boolean isFrom(double fromX, double fromY, Compass fromLane) {
            // bit for bit (Double.compare tells −0 from 0): the look is reused only where it is certainly the same
            return Double.compare(x, fromX) == 0 && Double.compare(y, fromY) == 0 && lane == fromLane;
        }
    }
}
