package sitcov.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.TreeMap;
import java.util.random.RandomGenerator;
import sitcov.coverage.Bins;
import sitcov.world.Layout;
import sitcov.world.MapGenerator;
import sitcov.world.ParkedCar;
import sitcov.world.SituationEdit;
import sitcov.world.WorldMap;

/**
 * Coverage search, MAP-Elites style (Mouret &amp; Clune 2015; DeepHyperion's illumination): keeps one
 * situation per covered cell (an elite), and instead of waiting for a random candidate to land in an
 * empty cell, edits an elite next to an empty cell — moves its Target or start, adds, moves or removes
 * a parked car — and runs the edit if it lands in a cell not yet covered. One candidate in
 * {@link #EXPLORE_EVERY} is still drawn at random, so the search keeps finding new regions of the grid
 * (and the first elites come from there). Every edit tried is charged as a candidate.
 */
final class CoverageSearchDriver implements Driver {
    /** One random candidate in this many, the rest edits. */
    static final int EXPLORE_EVERY = 4;
    /** Edits tried on one elite per candidate. */
    private static final int MAX_EDITS = 3;

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
        WorldMap parent = pickElite(session, choose);
        session.chargeBuilt();
        WorldMap child = parent;
        int edits = 1 + choose.nextInt(MAX_EDITS);
        for (int i = 0; i < edits; i++) {
            Optional<WorldMap> next = randomEdit(child.layout(), choose).apply(child);
            if (next.isEmpty()) {
                return;
            }
            child = next.get();
        }
        int cell = session.cellOf(child.layout());
        if (cell != Bins.INVALID && child.layout().isRunnable() && !session.covers(cell)) {
            session.run("search-r" + session.replication() + "-" + built++, child);
            elites.put(cell, child);
        }
    }

    /** An elite with an empty cell next to it, when there is one; any elite otherwise. */
    private WorldMap pickElite(DriverSession session, RandomGenerator choose) {
        List<Integer> frontier = new ArrayList<>();
        for (int cell : elites.keySet()) {
            if (hasEmptyNeighbour(session, cell)) {
                frontier.add(cell);
            }
        }
        List<Integer> from = frontier.isEmpty() ? new ArrayList<>(elites.keySet()) : frontier;
        return elites.get(from.get(choose.nextInt(from.size())));
    }

    /** Whether a cell one bin away in one criterion is still empty (cells number their bins mixed-radix, first slowest). */
    private static boolean hasEmptyNeighbour(DriverSession session, int cell) {
        List<Bins> bins = session.grid().bins();
        int stride = 1;
        for (int c = bins.size() - 1; c >= 0; c--) {
            int count = bins.get(c).count();
            int digit = (cell / stride) % count;
            if ((digit > 0 && !session.covers(cell - stride)) || (digit < count - 1 && !session.covers(cell + stride))) {
                return true;
            }
            stride *= count;
        }
        return false;
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
