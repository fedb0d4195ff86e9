package sitcov.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.TreeMap;
import java.util.random.RandomGenerator;
import sitcov.coverage.Bins;
import sitcov.coverage.Criterion;
import sitcov.coverage.GridDefinition;
import sitcov.world.Layout;
import sitcov.world.MapGenerator;
import sitcov.world.ParkedCar;
import sitcov.world.SituationEdit;
import sitcov.world.WorldMap;

/**
 * Coverage search, MAP-Elites style (Mouret &amp; Clune 2015; DeepHyperion's illumination): keeps one
 * situation per covered cell (an elite), and instead of waiting for a random candidate to land in an
 * empty cell, edits an elite next to an empty cell, aiming at it: a parked car added at the distance
 * from the Target the empty cell asks for (or the nearest removed), the start or the Target moved
 * along its road; it runs the edit if it lands in a cell not yet covered. One candidate in
 * {@link #EXPLORE_EVERY} is still drawn at random, so the search keeps finding new regions of the grid
 * (and the first elites come from there). Every edit tried is paid for with a candidate of the stream,
 * set aside, so the search is charged per candidate like the filter and its curves share their axis.
 */
final class CoverageSearchDriver implements Driver {
    /** One random candidate in this many, the rest edits. */
    static final int EXPLORE_EVERY = 2;

    private final TreeMap<Integer, WorldMap> elites = new TreeMap<>();
    private int built;

    @Override
    public void drive(DriverSession session) {
        RandomGenerator choose = session.choices();
        long step = 0;
        while (session.budgetLeft()) {
            if (elites.isEmpty() || step++ % EXPLORE_EVERY == 0) {
                explore(session);
            } else {
                search(session, choose);
            }
        }
    }

    private void explore(DriverSession session) {
        Candidate c = session.nextCandidate();
        if (c.runnable() && c.inGrid() && !session.covers(c.cell())) {
            session.run(c);
            elites.put(c.cell(), MapGenerator.withMovingCars(c.layout()));
        }
    }

    private void search(DriverSession session, RandomGenerator choose) {
        List<int[]> frontier = frontier(session);
        // the edit is paid for with the next candidate of the stream, set aside
        Candidate spent = session.nextCandidate();
        WorldMap parent;
        SituationEdit edit;
        if (frontier.isEmpty()) {
            List<Integer> all = new ArrayList<>(elites.keySet());
            parent = elites.get(all.get(choose.nextInt(all.size())));
            edit = randomEdit(parent.layout(), choose);
        } else {
            // an elite, a criterion in which the next bin is empty, and which way: aim the edit there
            int[] aim = frontier.get(choose.nextInt(frontier.size()));
            parent = elites.get(aim[0]);
            edit = aimedEdit(parent.layout(), session.grid(), aim[1], aim[2], aim[3], choose);
        }
        Optional<WorldMap> child = edit.apply(parent);
        if (child.isEmpty()) {
            return;
        }
        int cell = session.cellOf(child.get().layout());
        if (cell != Bins.INVALID && child.get().layout().isRunnable() && !session.covers(cell)) {
            session.run("search-r" + session.replication() + "-" + built++, child.get(), spent);
            elites.put(cell, child.get());
        }
    }

    /**
     * Every (elite cell, criterion, its bin there, step ±1) whose neighbouring cell is still empty;
     * cells number their bins mixed-radix, the first criterion slowest.
     */
    private List<int[]> frontier(DriverSession session) {
        List<Bins> bins = session.grid().bins();
        List<int[]> aims = new ArrayList<>();
        for (int cell : elites.keySet()) {
            int stride = 1;
            for (int c = bins.size() - 1; c >= 0; c--) {
                int count = bins.get(c).count();
                int digit = (cell / stride) % count;
                if (digit > 0 && !session.covers(cell - stride)) {
                    aims.add(new int[] {cell, c, digit, -1});
                }
                if (digit < count - 1 && !session.covers(cell + stride)) {
                    aims.add(new int[] {cell, c, digit, 1});
                }
                stride *= count;
            }
        }
        return aims;
    }

    /**
     * An edit meant to move criterion {@code c} from bin {@code digit} one bin up or down: the nearest
     * parked car nearer to or farther from the Target, the start or the Target moved along its road.
     * Which way along a road raises a distance is not known beforehand: a wrong guess lands elsewhere,
     * maybe in another empty cell, and costs one candidate.
     */
    private static SituationEdit aimedEdit(Layout layout, GridDefinition grid, int c, int digit, int step,
                                           RandomGenerator choose) {
        Criterion criterion = grid.criteria().get(c);
        Bins bins = grid.bins().get(c);
        double lo = bins.lower(digit + step);
        double hi = Math.min(bins.upper(digit + step), lo + 40);
        double wanted = lo + choose.nextDouble() * (hi - lo);
        double sign = choose.nextBoolean() ? 1 : -1;
        var target = layout.target().map(t -> t.position()).orElse(new sitcov.geom.Vec2(100, 50));
        return switch (criterion) {
            case TARGET_TO_OBSTACLE -> {
                ParkedCar nearest = layout.parkedCars().stream().min(java.util.Comparator.comparingDouble(
                        p -> p.centre().distanceTo(target.x(), target.y()))).orElse(null);
                if (step > 0 && nearest != null && choose.nextBoolean()) {
                    yield new SituationEdit.RemoveParkedCar(nearest.id());
                }
                // a parked car the wanted distance from the Target, along the road's axis either way
                boolean alongX = layout.roads().stream().filter(r -> r.id() == layout.target().get().roadId())
                        .findFirst().map(r -> !r.isNorthSouth()).orElse(true);
                yield alongX ? new SituationEdit.AddParkedCar(target.x() + sign * wanted, target.y())
                        : new SituationEdit.AddParkedCar(target.x(), target.y() + sign * wanted);
            }
            case START_TO_TARGET -> choose.nextBoolean() ? targetAtDistance(layout, wanted, choose)
                    .orElseGet(() -> new SituationEdit.MoveStart(sign * (10 + choose.nextDouble() * 50)))
                    : new SituationEdit.MoveStart(sign * (10 + choose.nextDouble() * 50));
            case PREVIOUS_JUNCTION_TO_TARGET -> new SituationEdit.MoveTarget(sign * (2 + choose.nextDouble() * 18));
        };
    }

    /**
     * The Target placed in a lane of a road drawn at random, {@code wanted} metres from the car's
     * start, where that road's lane passes at that distance (a root of |lane(t) − start| = wanted).
     */
    private static Optional<SituationEdit> targetAtDistance(Layout layout, double wanted, RandomGenerator choose) {
        if (layout.carStart().isEmpty() || layout.roads().isEmpty()) {
            return Optional.empty();
        }
        var start = layout.carStart().get().position();
        var road = layout.roads().get(choose.nextInt(layout.roads().size()));
        double across = road.centre() + (choose.nextBoolean() ? 1.5 : -1.5);
        var origin = road.point(0, across);
        double ex = road.isNorthSouth() ? 0 : 1;
        double ey = road.isNorthSouth() ? 1 : 0;
        double dx = origin.x() - start.x();
        double dy = origin.y() - start.y();
        double along = dx * ex + dy * ey;
        double discriminant = along * along - (dx * dx + dy * dy - wanted * wanted);
        if (discriminant < 0) {
            return Optional.empty();
        }
        double t = -along + (choose.nextBoolean() ? 1 : -1) * Math.sqrt(discriminant);
        if (t < road.from() || t > road.to()) {
            return Optional.empty();
        }
        var p = road.point(t, across);
        return Optional.of(new SituationEdit.PlaceTarget(p.x(), p.y()));
    }

    private static SituationEdit randomEdit(Layout layout, RandomGenerator choose) {
        List<ParkedCar> cars = layout.parkedCars();
        int kind = choose.nextInt(5);
        double sign = choose.nextBoolean() ? 1 : -1;
        if (kind == 0) {
            return new SituationEdit.MoveTarget(sign * (1 + choose.nextDouble() * 29));
        }
        if (kind == 1) {
            return new SituationEdit.MoveStart(sign * (5 + choose.nextDouble() * 55));
        }
        if (kind == 2 || cars.isEmpty()) {
            // a parked car near the Target (the first criterion measures how near the nearest is)
            var t = layout.target().map(x -> x.position()).orElse(new sitcov.geom.Vec2(100, 50));
            return new SituationEdit.AddParkedCar(t.x() + (choose.nextDouble() - 0.5) * 40,
                    t.y() + (choose.nextDouble() - 0.5) * 40);
        }
        ParkedCar car = cars.get(choose.nextInt(cars.size()));
        return kind == 3 ? new SituationEdit.RemoveParkedCar(car.id())
                : new SituationEdit.MoveParkedCar(car.id(), sign * (1 + choose.nextDouble() * 14));
    }
}
