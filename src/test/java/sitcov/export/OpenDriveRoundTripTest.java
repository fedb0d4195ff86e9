package sitcov.export;

import static sitcov.export.Frame.HEADING_TOLERANCE;
import static sitcov.export.Frame.METRE_TOLERANCE;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import sitcov.export.OpenDriveModel.Connection;
import sitcov.export.OpenDriveModel.Link;
import sitcov.export.OpenDriveModel.Road;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.world.Axis;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

/**
 * The OpenDRIVE export read back and evaluated independently (OpenDriveModel) lands on sitcov's own roads,
 * lanes and junctions within a centimetre, on many seeds (src/main/java/sitcov/export/README.md, "The frame").
 */
class OpenDriveRoundTripTest {
    private static final double HALF = Dimensions.JUNCTION_SIZE / 2;
    private static final double STEP = 0.5;
    private static List<Exported> exports;

    private record Exported(WorldMap map, OpenDriveModel model) {
        long seed() {
            return map.seed();
        }
    }

    private static synchronized List<Exported> exports() {
        if (exports == null) {
            exports = ExportSeeds.upTo(100).mapToObj(MapGenerator::generate)
                    .map(m -> new Exported(m, OpenDriveModel.parse(OpenDrive.document(m)))).toList();
        }
        return exports;
    }

    @Test
    void everyLaneCentreOutsideTheJunctionSquaresLiesOnExactlyOneLaneDrivenTheWaySitcovDrivesIt() {
        Failures failures = new Failures();
        for (Exported e : exports()) {
            for (sitcov.world.Road road : e.map().layout().roads()) {
                for (Compass direction : directions(road.axis())) {
                    double across = road.laneCentre(direction);
                    for (double along : samples(road, tJunctions(e.map()))) {
                        Vec2 p = road.point(along, across);
                        if (insideATJunction(e.map(), p)) {
                            continue;
                        }
                        // sitcov's own word on which way this lane is driven, not the direction we asked for
                        Compass driven = road.laneDirectionAt(p.x(), p.y());
                        String problem = coverage(e.model(), Frame.point(p), Frame.direction(driven));
                        if (problem != null) {
                            failures.add(e.seed(), "road " + road.id() + "'s " + driven + "-bound lane centre at " + p
                                    + " (exported " + Frame.point(p) + "): " + problem);
                            break; // one point of a lane tells it; the next lane may tell something else
                        }
                    }
                }
            }
        }
        failures.assertNone("a sitcov lane centre lies on exactly one exported lane, driven sitcov's way,");
    }

    @Test
    void everyRoadPieceRunsEastOrNorthAlongASitcovCentreLineBetweenRoadEndsAndJunctionSquares() {
        Failures failures = new Failures();
        for (Exported e : exports()) {
            Map<Junction, OpenDriveModel.Junction> matched = matchedJunctions(e).matched();
            for (Road piece : e.model().pieces()) {
                String problem = pieceProblem(e.map(), matched, piece);
                if (problem != null) {
                    failures.add(e.seed(), "road " + piece.id() + " from " + piece.start() + " to " + piece.end() + ": " + problem);
                }
            }
        }
        failures.assertNone("a road piece lies along a sitcov road, with two 3 m lanes, LHT, linked at its ends as the conventions say,");
    }

    @Test
    void everyTJunctionIsOneJunctionWhoseConnectingRoadsMeetItsArmsAtTheEdgesOfItsSquare() {
        Failures failures = new Failures();
        for (Exported e : exports()) {
            Matching m = matchedJunctions(e);
            m.problems().forEach(p -> failures.add(e.seed(), p));
            for (Junction j : tJunctions(e.map())) {
                if (!m.matched().containsKey(j)) {
                    failures.add(e.seed(), "no exported junction has its connecting roads end at T-junction " + j.id()
                            + "'s arms " + j.arms() + " (square centred on " + Frame.point(j.centre()) + " exported)");
                }
            }
        }
        failures.assertNone("every T-junction's square comes back from its connecting roads,");
    }

    @Test
    void everyJunctionConnectsEachArmToEachOtherArmFromTheLaneDrivingInToTheLaneDrivingOut() {
        Failures failures = new Failures();
        for (Exported e : exports()) {
            for (Map.Entry<Junction, OpenDriveModel.Junction> m : matchedJunctions(e).matched().entrySet()) {
                for (Compass from : m.getKey().arms()) {
                    for (Compass to : m.getKey().arms()) {
                        if (from != to) {
                            String problem = movementProblem(e, m.getKey(), m.getValue(), from, to);
                            if (problem != null) {
                                failures.add(e.seed(), "T-junction " + m.getKey().id() + " (exported junction "
                                        + m.getValue().id() + "), " + from + " arm to " + to + " arm: " + problem);
                            }
                        }
                    }
                }
                int expected = m.getKey().arms().size() * (m.getKey().arms().size() - 1);
                if (e.model().connectingRoads(m.getValue().id()).size() != expected) {
                    failures.add(e.seed(), "junction " + m.getValue().id() + " has "
                            + e.model().connectingRoads(m.getValue().id()).size() + " connecting roads, expected " + expected);
                }
            }
        }
        failures.assertNone("each movement through a T-junction has its connecting road and lane links,");
    }

    @Test
    void everyDeadEndIsAnOpenEndOfARoadPieceAtTheSitcovRoadEnd() {
        Failures failures = new Failures();
        int deadEnds = 0;
        for (Exported e : exports()) {
            for (Junction j : e.map().layout().junctions()) {
                if (!j.isDeadEnd()) {
                    continue;
                }
                deadEnds++;
                Compass arm = j.arms().get(0);
                sitcov.world.Road road = roadThrough(e.map(), j, arm);
                Vec2 end = road.start().distanceTo(j.centre()) < road.end().distanceTo(j.centre()) ? road.start() : road.end();
                Vec2 exported = Frame.point(end);
                List<String> found = new ArrayList<>();
                for (Road piece : e.model().pieces()) {
                    if (piece.start().distanceTo(exported) <= METRE_TOLERANCE) {
                        found.add(piece.predecessor().isEmpty() ? "open" : "linked to " + piece.predecessor().get());
                    }
                    if (piece.end().distanceTo(exported) <= METRE_TOLERANCE) {
                        found.add(piece.successor().isEmpty() ? "open" : "linked to " + piece.successor().get());
                    }
                }
                if (!found.equals(List.of("open"))) {
                    failures.add(e.seed(), "dead end " + j.id() + ": road " + road.id() + " ends at " + end + " (exported "
                            + exported + "), where the road pieces' ends are " + found + ", expected one open end");
                }
            }
        }
        failures.assertNone("a dead end is one open road end,");
        org.junit.jupiter.api.Assertions.assertTrue(deadEnds > 0, "the seeds have dead ends to check");
    }

    // ---- coverage of a lane centre point

    /** Null when exactly one exported lane's centre passes through {@code q}, driven along {@code driven}; else what is wrong. */
    private static String coverage(OpenDriveModel model, Vec2 q, Vec2 driven) {
        List<String> lanes = new ArrayList<>();
        String wrongWay = null;
        for (Road piece : model.pieces()) {
            if (!near(piece, q)) {
                continue;
            }
            for (OpenDriveModel.Geometry g : piece.geometry()) {
                double[] st = g.locate(q);
                if (st[0] < -METRE_TOLERANCE || st[0] > g.length() + METRE_TOLERANCE) {
                    continue;
                }
                double s = Math.min(Math.max(g.s() + st[0], 0), piece.length());
                for (OpenDriveModel.Lane lane : piece.lanes()) {
                    if (Math.abs(st[1] - piece.laneCentre(lane.id(), s)) > METRE_TOLERANCE) {
                        continue;
                    }
                    lanes.add("road " + piece.id() + " lane " + lane.id());
                    Vec2 d = piece.drivingDirection(lane.id(), s);
                    double cos = d.x() * driven.x() + d.y() * driven.y();
                    if (cos < Math.cos(HEADING_TOLERANCE)) {
                        wrongWay = "road " + piece.id() + " lane " + lane.id() + " is driven towards " + d
                                + " (rule " + (piece.leftHandTraffic() ? "LHT" : "not LHT") + ")";
                    } else if (!lane.type().equals("driving")) {
                        wrongWay = "road " + piece.id() + " lane " + lane.id() + " has type " + lane.type();
                    }
                }
            }
        }
        if (lanes.isEmpty()) {
            return "no exported lane's centre passes within 1 cm";
        }
        if (lanes.size() > 1) {
            return "the centres of " + lanes.size() + " lanes pass through it: " + lanes;
        }
        return wrongWay;
    }

    /** Whether {@code q} is within a road's width of the straight piece's reference line (pieces are lines, checked apart). */
    private static boolean near(Road piece, Vec2 q) {
        double reach = Dimensions.ROAD_WIDTH;
        Vec2 a = piece.start();
        Vec2 b = piece.end();
        return q.x() >= Math.min(a.x(), b.x()) - reach && q.x() <= Math.max(a.x(), b.x()) + reach
                && q.y() >= Math.min(a.y(), b.y()) - reach && q.y() <= Math.max(a.y(), b.y()) + reach;
    }

    private static List<Double> samples(sitcov.world.Road road, List<Junction> tJunctions) {
        TreeSet<Double> at = new TreeSet<>();
        for (double a = road.from(); a < road.to(); a += STEP) {
            at.add(a);
        }
        at.add(road.to());
        for (Junction j : tJunctions) {
            if (road.carries(j.centre())) {
                double c = road.along(j.centre().x(), j.centre().y());
                for (double edge : new double[] {c - HALF, c + HALF}) {
                    if (edge >= road.from() && edge <= road.to()) {
                        at.add(edge);
                    }
                }
            }
        }
        return new ArrayList<>(at);
    }

    private static boolean insideATJunction(WorldMap map, Vec2 p) {
        return tJunctions(map).stream().anyMatch(j -> Math.abs(p.x() - j.centre().x()) < HALF - 1e-6
                && Math.abs(p.y() - j.centre().y()) < HALF - 1e-6);
    }

    // ---- road pieces

    private static String pieceProblem(WorldMap map, Map<Junction, OpenDriveModel.Junction> matched, Road piece) {
        if (piece.geometry().size() != 1 || !piece.geometry().get(0).isLine()) {
            return "its plan view is not one <line>";
        }
        if (!piece.leftHandTraffic()) {
            return "its rule is not LHT";
        }
        double hdg = piece.geometry().get(0).hdg();
        Axis axis = Frame.angleBetween(hdg, 0) <= HEADING_TOLERANCE ? Axis.EAST_WEST
                : Frame.angleBetween(hdg, Math.PI / 2) <= HEADING_TOLERANCE ? Axis.NORTH_SOUTH : null;
        if (axis == null) {
            return "it heads " + hdg + " rad, neither east (0) nor north (π/2)";
        }
        if (Math.abs(piece.length() - piece.start().distanceTo(piece.end())) > METRE_TOLERANCE) {
            return "its length " + piece.length() + " is not its line's";
        }
        for (int lane : new int[] {1, -1}) {
            for (double s : new double[] {0, piece.length()}) {
                if (piece.lane(lane).isEmpty() || Math.abs(Math.abs(piece.laneCentre(lane, s)) - 1.5) > METRE_TOLERANCE) {
                    return "its lane " + lane + " is not 3 m wide on its side of the reference line at s=" + s;
                }
            }
        }
        if (piece.lanes().size() != 2) {
            return "it has " + piece.lanes().size() + " lanes, expected lanes 1 and -1";
        }
        Vec2 a = back(piece.start());
        Vec2 b = back(piece.end());
        sitcov.world.Road road = map.layout().roads().stream().filter(r -> r.axis() == axis && onCentreLine(r, a) && onCentreLine(r, b))
                .findFirst().orElse(null);
        if (road == null) {
            return "it lies on no sitcov road's centre line (sitcov " + a + " to " + b + ")";
        }
        double from = road.along(a.x(), a.y());
        double to = road.along(b.x(), b.y());
        for (Junction j : tJunctions(map)) {
            if (road.carries(j.centre())) {
                double c = road.along(j.centre().x(), j.centre().y());
                if (Math.min(from, to) < c + HALF - METRE_TOLERANCE && Math.max(from, to) > c - HALF + METRE_TOLERANCE) {
                    return "it enters T-junction " + j.id() + "'s square";
                }
            }
        }
        String start = endProblem(map, matched, road, from, piece.predecessor(), "start");
        return start != null ? start : endProblem(map, matched, road, to, piece.successor(), "end");
    }

    /** Null when the piece's end at {@code along} is an open sitcov road end or links to the junction whose square it meets. */
    private static String endProblem(WorldMap map, Map<Junction, OpenDriveModel.Junction> matched, sitcov.world.Road road,
                                     double along, Optional<Link> link, String which) {
        for (Junction j : tJunctions(map)) {
            if (road.carries(j.centre())) {
                double c = road.along(j.centre().x(), j.centre().y());
                if (Math.abs(Math.abs(along - c) - HALF) <= METRE_TOLERANCE) {
                    OpenDriveModel.Junction exported = matched.get(j);
                    String expected = exported == null ? "(unmatched)" : exported.id();
                    if (link.isEmpty() || !link.get().elementType().equals("junction")
                            || !link.get().elementId().equals(expected)) {
                        return "its " + which + " meets T-junction " + j.id() + "'s square but links to "
                                + link.map(Link::toString).orElse("nothing") + ", expected junction " + expected;
                    }
                    return null;
                }
            }
        }
        if (Math.abs(along - road.from()) <= METRE_TOLERANCE || Math.abs(along - road.to()) <= METRE_TOLERANCE) {
            return link.isEmpty() ? null : "its " + which + " is the end of sitcov road " + road.id()
                    + " (a dead end), an open end, but links to " + link.get();
        }
        return "its " + which + " is neither an end of sitcov road " + road.id() + " nor the edge of a T-junction square";
    }

    private static boolean onCentreLine(sitcov.world.Road r, Vec2 p) {
        double along = r.along(p.x(), p.y());
        return Math.abs(r.across(p.x(), p.y()) - r.centre()) <= METRE_TOLERANCE
                && along >= r.from() - METRE_TOLERANCE && along <= r.to() + METRE_TOLERANCE;
    }

    // ---- junctions

    private record Matching(Map<Junction, OpenDriveModel.Junction> matched, List<String> problems) {
    }

    /** Each exported junction paired with the sitcov T-junction whose arm points (centre + 3 m along each arm) its connecting roads end at. */
    private static Matching matchedJunctions(Exported e) {
        Map<Junction, OpenDriveModel.Junction> matched = new LinkedHashMap<>();
        List<String> problems = new ArrayList<>();
        for (OpenDriveModel.Junction oj : e.model().junctions().values()) {
            List<Vec2> ends = new ArrayList<>();
            for (Road c : e.model().connectingRoads(oj.id())) {
                ends.add(c.start());
                ends.add(c.end());
            }
            List<Junction> fits = tJunctions(e.map()).stream().filter(j -> sameSet(ends, armPoints(j))).toList();
            if (fits.size() != 1) {
                problems.add("junction " + oj.id() + "'s connecting roads end at " + distinct(ends)
                        + ", the arm points of " + fits.size() + " sitcov T-junctions");
            } else if (matched.put(fits.get(0), oj) != null) {
                problems.add("T-junction " + fits.get(0).id() + " is exported twice");
            }
        }
        return new Matching(matched, problems);
    }

    private static String movementProblem(Exported e, Junction j, OpenDriveModel.Junction oj, Compass from, Compass to) {
        Vec2 in = armPoint(j, from);
        Vec2 out = armPoint(j, to);
        List<Road> roads = e.model().connectingRoads(oj.id()).stream()
                .filter(c -> c.start().distanceTo(in) <= METRE_TOLERANCE && c.end().distanceTo(out) <= METRE_TOLERANCE).toList();
        if (roads.size() != 1) {
            return roads.size() + " connecting roads run from " + in + " to " + out;
        }
        Road c = roads.get(0);
        String shape = shapeProblem(c, from == to.opposite());
        if (shape != null) {
            return "connecting road " + c.id() + " " + shape;
        }
        // its one lane, from sitcov's lane driving in on the one arm to sitcov's lane driving out on the other
        Vec2 laneIn = Frame.point(lanePoint(e.map(), j, from, from.opposite()));
        Vec2 laneOut = Frame.point(lanePoint(e.map(), j, to, to));
        if (c.lanes().size() != 1 || c.lane(1).isEmpty()) {
            return "connecting road " + c.id() + " does not carry exactly lane 1";
        }
        if (!c.drivenAlongReference(1)) {
            return "connecting road " + c.id() + "'s lane 1 is not driven along its reference line (rule LHT)";
        }
        Vec2 start = c.point(0, c.laneCentre(1, 0));
        Vec2 end = c.point(c.length(), c.laneCentre(1, c.length()));
        if (start.distanceTo(laneIn) > METRE_TOLERANCE || end.distanceTo(laneOut) > METRE_TOLERANCE) {
            return "connecting road " + c.id() + "'s lane runs from " + start + " to " + end + ", sitcov's lanes meet the square at "
                    + laneIn + " and " + laneOut;
        }
        Road incoming = pieceAt(e.model(), in);
        Road outgoing = pieceAt(e.model(), out);
        if (incoming == null || outgoing == null) {
            return "no road piece (or more than one) ends at the " + (incoming == null ? from : to) + " arm";
        }
        int laneFrom = laneDriving(incoming, in, Frame.direction(from.opposite()));
        int laneTo = laneDriving(outgoing, out, Frame.direction(to));
        List<Connection> connections = oj.connections().stream().filter(k -> k.connectingRoad().equals(c.id())).toList();
        if (connections.size() != 1) {
            return connections.size() + " <connection>s name connecting road " + c.id();
        }
        Connection k = connections.get(0);
        if (!k.incomingRoad().equals(incoming.id()) || !k.contactPoint().equals("start")) {
            return "its connection comes from road " + k.incomingRoad() + " at its " + k.contactPoint()
                    + ", expected road " + incoming.id() + " at the connecting road's start";
        }
        if (k.laneLinks().size() != 1 || k.laneLinks().get(0)[0] != laneFrom || k.laneLinks().get(0)[1] != 1) {
            return "its connection's lane links are " + k.laneLinks().stream().map(l -> l[0] + "->" + l[1]).toList()
                    + ", expected " + laneFrom + "->1 (road " + incoming.id() + "'s lane driving into the junction)";
        }
        String links = roadLinkProblem(c.predecessor(), incoming, in, "predecessor");
        if (links == null) {
            links = roadLinkProblem(c.successor(), outgoing, out, "successor");
        }
        if (links != null) {
            return "connecting road " + c.id() + " " + links;
        }
        OpenDriveModel.Lane lane = c.lane(1).get();
        if (!lane.predecessor().equals(Optional.of(laneFrom)) || !lane.successor().equals(Optional.of(laneTo))) {
            return "connecting road " + c.id() + "'s lane 1 links from lane " + lane.predecessor().orElse(null) + " to lane "
                    + lane.successor().orElse(null) + ", expected from " + laneFrom + " (road " + incoming.id()
                    + ", driving in) to " + laneTo + " (road " + outgoing.id() + ", driving out)";
        }
        return null;
    }

    /** A 6 m straight line across, or a quarter circle of radius 3 m turning the right way; null when so. */
    private static String shapeProblem(Road c, boolean straight) {
        if (c.geometry().size() != 1) {
            return "has " + c.geometry().size() + " geometries, expected one";
        }
        OpenDriveModel.Geometry g = c.geometry().get(0);
        double length = straight ? Dimensions.JUNCTION_SIZE : 3 * Math.PI / 2;
        if (straight != g.isLine() || Math.abs(g.length() - length) > METRE_TOLERANCE
                || Math.abs(c.length() - length) > METRE_TOLERANCE) {
            return "is a " + g.kind() + " of " + g.length() + " m, expected a " + (straight ? "line" : "arc") + " of " + length + " m";
        }
        if (!straight && Math.abs(Math.abs(g.curvature()) - 1.0 / 3) > 1e-6) {
            return "has curvature " + g.curvature() + ", expected ±1/3";
        }
        return null;
    }

    /** Null when {@code link} names {@code piece}, at the end of it that touches {@code at}. */
    private static String roadLinkProblem(Optional<Link> link, Road piece, Vec2 at, String which) {
        String contact = piece.start().distanceTo(at) <= METRE_TOLERANCE ? "start" : "end";
        if (link.isEmpty() || !link.get().elementType().equals("road") || !link.get().elementId().equals(piece.id())
                || !link.get().contactPoint().equals(Optional.of(contact))) {
            return "has " + which + " " + link.map(Link::toString).orElse("none") + ", expected road " + piece.id() + " at its " + contact;
        }
        return null;
    }

    /** The one road piece with an end at {@code p}, or null. */
    private static Road pieceAt(OpenDriveModel model, Vec2 p) {
        List<Road> at = model.pieces().stream()
                .filter(r -> r.start().distanceTo(p) <= METRE_TOLERANCE || r.end().distanceTo(p) <= METRE_TOLERANCE).toList();
        return at.size() == 1 ? at.get(0) : null;
    }

    /** The id of {@code piece}'s lane driven along {@code direction} at its end {@code at} (0 when none). */
    private static int laneDriving(Road piece, Vec2 at, Vec2 direction) {
        double s = piece.start().distanceTo(at) <= METRE_TOLERANCE ? 0 : piece.length();
        for (OpenDriveModel.Lane lane : piece.lanes()) {
            Vec2 d = piece.drivingDirection(lane.id(), s);
            if (d.x() * direction.x() + d.y() * direction.y() > Math.cos(HEADING_TOLERANCE)) {
                return lane.id();
            }
        }
        return 0;
    }

    /** Where sitcov's lane driven along {@code driven} on arm {@code arm} of {@code j} meets the square (sitcov frame). */
    private static Vec2 lanePoint(WorldMap map, Junction j, Compass arm, Compass driven) {
        sitcov.world.Road road = roadThrough(map, j, arm);
        Vec2 edge = new Vec2(j.centre().x() + arm.dx() * HALF, j.centre().y() + arm.dy() * HALF);
        return road.point(road.along(edge.x(), edge.y()), road.laneCentre(driven));
    }

    /** The sitcov road that runs through {@code j}'s centre along {@code arm}. */
    private static sitcov.world.Road roadThrough(WorldMap map, Junction j, Compass arm) {
        return map.layout().roads().stream().filter(r -> r.axis() == Axis.of(arm) && r.carries(j.centre())).findFirst()
                .orElseThrow(() -> new AssertionError("no sitcov road runs " + arm + " through junction " + j.id()));
    }

    /** Where the centre line of arm {@code arm} meets {@code j}'s square, exported. */
    private static Vec2 armPoint(Junction j, Compass arm) {
        return Frame.point(j.centre().x() + arm.dx() * HALF, j.centre().y() + arm.dy() * HALF);
    }

    private static List<Vec2> armPoints(Junction j) {
        return j.arms().stream().map(a -> armPoint(j, a)).toList();
    }

    private static boolean sameSet(List<Vec2> found, List<Vec2> expected) {
        return found.stream().allMatch(f -> expected.stream().anyMatch(x -> x.distanceTo(f) <= METRE_TOLERANCE))
                && expected.stream().allMatch(x -> found.stream().anyMatch(f -> x.distanceTo(f) <= METRE_TOLERANCE));
    }

    private static List<Vec2> distinct(List<Vec2> points) {
        List<Vec2> out = new ArrayList<>();
        for (Vec2 p : points) {
            if (out.stream().noneMatch(o -> o.distanceTo(p) <= METRE_TOLERANCE)) {
                out.add(p);
            }
        }
        return out;
    }

    private static List<Junction> tJunctions(WorldMap map) {
        return map.layout().junctions().stream().filter(j -> !j.isDeadEnd()).toList();
    }

    private static List<Compass> directions(Axis axis) {
        return axis == Axis.NORTH_SOUTH ? List.of(Compass.NORTH, Compass.SOUTH) : List.of(Compass.EAST, Compass.WEST);
    }

    /** An exported point back in sitcov's frame. */
    private static Vec2 back(Vec2 exported) {
        return Frame.point(exported); // the flip y ↦ 100 − y is its own inverse
    }
}
