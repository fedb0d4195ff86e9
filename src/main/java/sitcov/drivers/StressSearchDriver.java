package sitcov.drivers;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.random.RandomGenerator;
import sitcov.experiment.Candidate;
import sitcov.experiment.Driver;
import sitcov.experiment.DriverSession;
import sitcov.experiment.MapRun;
import sitcov.oracle.AccidentType;
import sitcov.world.MapGenerator;
import sitcov.world.SituationEdit;
import sitcov.world.WorldMap;

/**
 * Stress search, black-box: looks for situations in which the reference car (the fault-free runs)
 * comes nearest to failing, and so for its own failures and the situations faults turn into
 * failures. It reads of a run only the fault-free run's robustness ({@link Stress}) and its cell,
 * never the faults or their outcomes.
 *
 * <p>MAP-Elites over the coverage cells with stress as the fitness: an archive keeps, per cell, the
 * least robust situation run there. The step is simulated annealing (Kirkpatrick et al. 1983): a
 * current situation is edited (a {@link SituationEdit} drawn at random, the traffic reseeded, or the
 * same situation under a new name, which gives it a new internal seed), the child is run and kept in
 * its cell's place if it is less robust than the elite there, and it becomes the current situation
 * if it is less robust, or else with probability exp(−Δ/T), T falling linearly from {@link #HOT} to
 * {@link #COLD} over the budget. Every failure counts as stress {@link Stress#FAILED}, so a walk that
 * has found one wanders among its failing neighbours (a failure's edits often fail too). After
 * {@link #PATIENCE} steps that neither lowered the walk's least stress nor failed in a cell × accident
 * type not failed in before, the walk starts again from an elite of a cell that has not failed yet,
 * the less robust of two drawn (a tournament), so failures spread over cells. Once the archive holds a
 * failure, half the other steps edit a failing elite instead of annealing (measured on 15 failing maps:
 * 47 % of their edits, 53 % of traffic reseeds and 73 % of new internal seeds failed again). One
 * candidate in {@link #EXPLORE_EVERY} is drawn at random and run if its cell is empty, so the archive
 * keeps growing. Every edit is paid for with a candidate of the stream, set aside, like
 * coverage-search's.
 *
 * <p>In the campaign of one of the reference's own requirements (experiments/README.md, "Requirement campaigns:
 * where your controller itself fails") stress is that requirement's ρ alone, and only its failures are failures;
 * the controller's own requirement has no ρ, so there it keeps the least over all types.
 */
final class StressSearchDriver implements Driver {
    static final int EXPLORE_EVERY = 4;
    /** An edit that breaks a rule of the world is drawn again, at most this many times. */
    static final int DRAWS = 20;
    static final double HOT = 0.3;
    static final double COLD = 0.02;
    static final int PATIENCE = 20;

    private record Elite(WorldMap map, double stress) {
    }

    private final TreeMap<Integer, Elite> archive = new TreeMap<>();
    /** The accident type whose ρ alone is the stress, in a requirement campaign; else the least of all counts. */
    private Optional<AccidentType> aim = Optional.empty();
    private final Set<Integer> failed = new HashSet<>();
    private WorldMap current;
    private double currentStress;
    private double bestOfWalk;
    private int stale;
    private int built;
    private long step;

    @Override
    public void drive(DriverSession session) {
        RandomGenerator choose = session.choices();
        aim = session.requirement().flatMap(r -> r.robustness());
        while (session.budgetLeft()) {
            if (archive.isEmpty() || step++ % EXPLORE_EVERY == 0) {
                explore(session);
            } else if (choose.nextBoolean() && hasFailures()) {
                exploit(session, choose);
            } else {
                anneal(session, choose);
            }
        }
    }

    private void explore(DriverSession session) {
        Candidate c = session.nextCandidate();
        if (c.runnable() && c.inGrid() && !session.covers(c.cell())) {
            WorldMap map = MapGenerator.withMovingCars(c.layout());
            keep(session.run(c), map);
        }
    }

    private void anneal(DriverSession session, RandomGenerator choose) {
        if (current == null || stale >= PATIENCE) {
            restart(choose);
        }
        Candidate spent = session.nextCandidate();
        Optional<WorldMap> child = Optional.empty();
        for (int draw = 0; draw < DRAWS && child.isEmpty(); draw++) {
            child = mutation(current, choose);
        }
        if (child.isEmpty() || !child.get().layout().isRunnable()) {
            stale++;
            return;
        }
        MapRun run = session.run("stress-r" + session.replication() + "-" + built++, child.get(), spent);
        boolean newFailure = newFailure(run);
        double stress = keep(run, child.get());
        // a failure found before is worth less to the walk than a new one: it moves on from it
        double walkStress = stress <= Stress.FAILED && !newFailure ? Stress.FAILED / 2 : stress;
        double temperature = HOT + (COLD - HOT) * session.budgetSpent();
        // the draw is made whatever the comparison, so the stream does not depend on it
        double u = choose.nextDouble();
        if (walkStress < currentStress || u < Math.exp(-(walkStress - currentStress) / temperature)) {
            current = child.get();
            currentStress = walkStress;
        }
        if (stress < bestOfWalk || newFailure) {
            bestOfWalk = Math.min(bestOfWalk, stress);
            stale = 0;
        } else {
            stale++;
        }
    }

    private boolean hasFailures() {
        return archive.values().stream().anyMatch(e -> e.stress() <= Stress.FAILED);
    }

    /** A failing elite, drawn evenly, edited: about half of a failure's edits fail too, many of them in other cells. */
    private void exploit(DriverSession session, RandomGenerator choose) {
        List<Elite> failing = archive.values().stream().filter(e -> e.stress() <= Stress.FAILED).toList();
        WorldMap parent = failing.get(choose.nextInt(failing.size())).map();
        Candidate spent = session.nextCandidate();
        Optional<WorldMap> child = Optional.empty();
        for (int draw = 0; draw < DRAWS && child.isEmpty(); draw++) {
            child = AimedEdits.random(parent.layout(), choose).apply(parent);
        }
        if (child.isPresent() && child.get().layout().isRunnable()) {
            MapRun run = session.run("stress-r" + session.replication() + "-" + built++, child.get(), spent);
            newFailure(run);
            keep(run, child.get());
        }
    }

    /** The situation edited, its traffic reseeded, or as it is (run under a new name: a new internal seed); empty when the edit breaks a rule of the world. */
    private static Optional<WorldMap> mutation(WorldMap map, RandomGenerator choose) {
        return switch (choose.nextInt(4)) {
            case 0 -> new SituationEdit.ReseedTraffic(choose.nextLong()).apply(map);
            case 1 -> Optional.of(map);
            default -> AimedEdits.random(map.layout(), choose).apply(map);
        };
    }

    /** A new walk from an elite of a cell where the reference has not failed: the less robust of two drawn. */
    private void restart(RandomGenerator choose) {
        List<Elite> open = new ArrayList<>();
        for (Elite e : archive.values()) {
            if (e.stress() > Stress.FAILED) {
                open.add(e);
            }
        }
        List<Elite> from = open.isEmpty() ? new ArrayList<>(archive.values()) : open;
        Elite a = from.get(choose.nextInt(from.size()));
        Elite b = from.get(choose.nextInt(from.size()));
        Elite start = b.stress() < a.stress() ? b : a;
        current = start.map();
        currentStress = start.stress();
        bestOfWalk = currentStress;
        stale = 0;
    }

    /** Whether the reference failed in this run in a way (cell × accident type) it had not failed before. */
    private boolean newFailure(MapRun run) {
        boolean any = false;
        for (AccidentType t : aim.map(List::of).orElse(List.of(AccidentType.values()))) {
            if (run.faultFree().margins().robustness(t) < 0) {
                any |= failed.add(run.cell() * AccidentType.values().length + t.ordinal());
            }
        }
        return any;
    }

    private double stress(MapRun run) {
        return aim.map(t -> Stress.of(run.faultFree().margins(), t)).orElseGet(() -> Stress.of(run.faultFree().margins()));
    }

    /** Keeps the run's situation as its cell's elite if it is less robust; its stress. */
    private double keep(MapRun run, WorldMap map) {
        // every failure is as good as any other: the walk wanders among them, into other cells
        double stress = Math.max(Stress.FAILED, stress(run));
        Elite there = archive.get(run.cell());
        if (run.cell() >= 0 && (there == null || stress < there.stress())) {
            archive.put(run.cell(), new Elite(map, stress));
        }
        return stress;
    }
}
