package sitcov.drivers;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.TreeMap;
import java.util.random.RandomGenerator;
import sitcov.coverage.Bins;
import sitcov.coverage.GridDefinition;
import sitcov.experiment.Candidate;
import sitcov.experiment.Driver;
import sitcov.experiment.DriverSession;
import sitcov.world.MapGenerator;
import sitcov.world.SituationEdit;
import sitcov.world.WorldMap;

/**
 * Coverage search, MAP-Elites style (Mouret &amp; Clune 2015; DeepHyperion's illumination): keeps one
 * situation per covered cell (an elite), and instead of waiting for a random candidate to land in an
 * empty cell, edits an elite next to an empty cell, aiming at it ({@link AimedEdits}: a parked car
 * added at the distance from the Target the empty cell asks for, a branch road added where the
 * junction behind the Target should be, the Target placed on a new branch far from the start, ...);
 * it runs the edit if it lands in a cell not yet covered. One candidate in
 * {@link #EXPLORE_EVERY} is still drawn at random, so the search keeps finding new regions of the grid
 * (and the first elites come from there). Every edit tried is paid for with a candidate of the stream,
 * set aside, so the search is charged per candidate like the filter and its curves share their axis.
 */
final class CoverageSearchDriver implements Driver {
    /** One random candidate in this many, the rest edits. */
    static final int EXPLORE_EVERY = 2;
    /** An edit that breaks a rule of the world is drawn again, at most this many times in all. */
    static final int DRAWS = 20;

    private final TreeMap<Integer, WorldMap> elites = new TreeMap<>();
    private final ElitePreference preference;
    /** Names its situations {@code <prefix>-r<replication>-<n>}, unique in a results folder. */
    private final String prefix;
    private int built;

    /** coverage-search: every elite alike. */
    CoverageSearchDriver() {
        this(ElitePreference.EVEN, "search");
    }

    CoverageSearchDriver(ElitePreference preference, String prefix) {
        this.preference = preference;
        this.prefix = prefix;
    }

    /** fault-search: elites whose maps found rare faults edited more often. */
    static CoverageSearchDriver faultSearch() {
        return new CoverageSearchDriver(new ElitePreference.RareFaults(), "fault-search");
    }

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
            preference.ran(c.cell(), session.run(c));
            elites.put(c.cell(), MapGenerator.withMovingCars(c.layout()));
        }
    }

    private void search(DriverSession session, RandomGenerator choose) {
        List<Aim> frontier = frontier(session);
        // the edit is paid for with the next candidate of the stream, set aside
        Candidate spent = session.nextCandidate();
        WorldMap parent;
        Aim aim = null;
        if (frontier.isEmpty()) {
            List<Integer> all = new ArrayList<>(elites.keySet());
            parent = elites.get(all.get(choose.nextInt(all.size())));
        } else {
            // an elite, a criterion in which the next bin is empty, and which way: aim the edit there
            aim = pick(frontier, choose);
            parent = elites.get(aim.elite());
        }
        // one candidate is one situation that keeps the world's rules, as the generator's are: an edit
        // that breaks one is drawn again, as the generator draws a parked car's place again
        Optional<WorldMap> child = Optional.empty();
        for (int draw = 0; draw < DRAWS && child.isEmpty(); draw++) {
            SituationEdit edit = aim == null ? AimedEdits.random(parent.layout(), choose)
                    : AimedEdits.toward(parent, session.grid(), aim.criterion(), aim.bin(), aim.step(), choose);
            child = edit.apply(parent);
        }
        if (child.isEmpty()) {
            return;
        }
        int cell = session.cellOf(child.get().layout());
        if (cell != Bins.INVALID && child.get().layout().isRunnable() && !session.covers(cell)) {
            preference.ran(cell, session.run(prefix + "-r" + session.replication() + "-" + built++, child.get(), spent));
            elites.put(cell, child.get());
        }
    }

    /** An aim drawn evenly, or by the weight of its elite. */
    private Aim pick(List<Aim> frontier, RandomGenerator choose) {
        if (preference.even()) {
            return frontier.get(choose.nextInt(frontier.size()));
        }
        double[] upTo = new double[frontier.size()];
        double total = 0;
        for (int i = 0; i < upTo.length; i++) {
            total += preference.weight(frontier.get(i).elite());
            upTo[i] = total;
        }
        double draw = choose.nextDouble() * total;
        for (int i = 0; i < upTo.length; i++) {
            if (draw < upTo[i]) {
                return frontier.get(i);
            }
        }
        return frontier.get(upTo.length - 1);
    }

    /** Every aim at an empty cell next to an elite: the elites in cell order, each's neighbours in the grid's order. */
    private List<Aim> frontier(DriverSession session) {
        List<Aim> aims = new ArrayList<>();
        for (int cell : elites.keySet()) {
            for (GridDefinition.Neighbour next : session.grid().neighbours(cell)) {
                if (!session.covers(next.cell())) {
                    aims.add(new Aim(cell, next.criterion(), next.bin(), next.step()));
                }
            }
        }
        return aims;
    }

    /**
     * An edit's aim: the elite in cell {@code elite}, whose criterion {@code criterion} is in bin
     * {@code bin}, edited towards the empty cell one bin {@code step} (±1) away in that criterion.
     */
    record Aim(int elite, int criterion, int bin, int step) {
    }
}
