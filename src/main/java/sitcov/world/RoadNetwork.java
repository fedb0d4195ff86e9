package sitcov.world;

import static sitcov.world.Dimensions.CENTRE_LINE_WIDTH;
import static sitcov.world.Dimensions.EDGE_LINE_OFFSET;
import static sitcov.world.Dimensions.EDGE_LINE_WIDTH;
import static sitcov.world.Dimensions.HALF_ROAD;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import sitcov.geom.Box;
import sitcov.geom.Compass;
import sitcov.geom.Rect;
import sitcov.geom.Vec2;

/**
 * Spatial questions about a set of roads and junctions: what is at a point, where the lanes and
 * markings are, whether a footprint stays on the road. Built once per layout; immutable.
 */
public final class RoadNetwork {
    private final List<Road> roads;
    private final List<Junction> junctions;
    private final List<Rect> surfaces;
    private final List<Rect> zones;
    private final List<Marking> markings;
    /** What a run asks of the network each tick, worked out on first use (map generation never asks). */
    private volatile Lookups lookups;

    public RoadNetwork(List<Road> roads, List<Junction> junctions) {
        this.roads = List.copyOf(roads);
        this.junctions = List.copyOf(junctions);
        this.surfaces = this.roads.stream().map(Road::surface).toList();
        List<Rect> allZones = new ArrayList<>();
        for (Junction j : this.junctions) {
            allZones.addAll(j.approachZone());
            allZones.addAll(j.exitZone());
        }
        this.zones = List.copyOf(allZones);
        List<Marking> paint = new ArrayList<>();
        for (Road road : this.roads) {
            paint.addAll(markingsOf(road));
        }
        this.markings = List.copyOf(paint);
    }

    private Lookups lookups() {
        Lookups made = lookups;
        if (made == null) {
            made = new Lookups(this);
            lookups = made;
        }
        return made;
    }

    /** Immutable once made; two threads that both make it make equal ones. */
    private static final class Lookups {
        private final List<Junction> deadEnds;
        /** Per road, the junctions whose centre it carries, in junction order: cars ask each tick what junction is next. */
        private final Map<Road, List<Junction>> junctionsOn = new IdentityHashMap<>();
        /** Per kind and axis, the markings whose strips run along that axis, in marking order: the camera looks for these. */
        private final Map<MarkingKind, Map<Axis, List<Marking>>> markingsAlong = new EnumMap<>(MarkingKind.class);
        /** Which roads can hold a point: cars and the oracle ask where they are many times a tick. */
        private final RoadGrid grid;

        private Lookups(RoadNetwork network) {
            deadEnds = network.junctions.stream().filter(Junction::isDeadEnd).toList();
            grid = new RoadGrid(network.roads);
            for (Road road : network.roads) {
                junctionsOn.put(road, network.carried(road));
            }
            for (MarkingKind kind : MarkingKind.values()) {
                Map<Axis, List<Marking>> byAxis = new EnumMap<>(Axis.class);
                for (Axis axis : Axis.values()) {
                    byAxis.put(axis, network.markings.stream()
                            .filter(m -> m.kind() == kind && runsAlong(m.strip(), axis)).toList());
                }
                markingsAlong.put(kind, byAxis);
            }
        }
    }

    private List<Junction> carried(Road road) {
        return junctions.stream().filter(j -> road.carries(j.centre())).toList();
    }

    private static boolean runsAlong(Rect strip, Axis axis) {
        return axis == Axis.NORTH_SOUTH ? strip.height() > strip.width() : strip.width() > strip.height();
    }

    public static RoadNetwork of(Layout layout) {
        return new RoadNetwork(layout.roads(), layout.junctions());
    }

    public List<Road> roads() {
        return roads;
    }

    public List<Junction> junctions() {
        return junctions;
    }

    /** The road surfaces, one rectangle a road, in road order. */
    public List<Rect> surfaces() {
        return surfaces;
    }

    /** Edge and centre lines, cut wherever a junction square crosses the road. */
    public List<Marking> markings() {
        return markings;
    }

    /** The dead ends, in junction order: where moving cars leave and enter. */
    public List<Junction> deadEnds() {
        return lookups().deadEnds;
    }

    /** The junctions whose centre lies on {@code road}'s axis between its ends, in junction order. */
    public List<Junction> junctionsOn(Road road) {
        List<Junction> on = lookups().junctionsOn.get(road);
        return on != null ? on : carried(road);
    }

    /** The markings of {@code kind} whose strips are longer along {@code axis} than across it, in marking order. */
    public List<Marking> markings(MarkingKind kind, Axis axis) {
        return lookups().markingsAlong.get(kind).get(axis);
    }

    /**
     * The indices in {@link #roads()}, in road order, of the roads that can hold the point: every road
     * that holds it is among them, so scanning them in order finds what scanning every road finds.
     * The array is shared: read it, never write it.
     */
    public int[] roadsNear(double x, double y) {
        return lookups().grid.near(x, y);
    }

    /** The first road (in road order) whose surface holds the point, or null. */
    public Road roadAt(double x, double y) {
        for (Road road : roads) {
            if (road.contains(x, y)) {
                return road;
            }
        }
        return null;
    }

    public boolean isOnRoad(double x, double y) {
        return roadAt(x, y) != null;
    }

    /** The junction whose square holds the point, or null. */
    public Junction junctionAt(double x, double y) {
        for (Junction junction : junctions) {
            if (junction.contains(x, y)) {
                return junction;
            }
        }
        return null;
    }

    public boolean isInJunction(double x, double y) {
        return junctionAt(x, y) != null;
    }

    /** Whether the footprint's interior meets any junction square. */
    public boolean overlapsJunction(Box footprint) {
        for (Junction junction : junctions) {
            if (footprint.overlaps(junction.square())) {
                return true;
            }
        }
        return false;
    }

    /** Whether the point lies in any junction's square or approach or exit zone. */
    public boolean isInJunctionZone(double x, double y) {
        for (Rect zone : zones) {
            if (zone.contains(x, y)) {
                return true;
            }
        }
        return false;
    }

    /** Whether every part of the footprint is on the road surface. */
    public boolean isOnRoad(Box footprint) {
        Rect bounds = footprint.bounds();
        for (Rect surface : surfaces) {
            if (surface.contains(bounds)) {
                return true; // the usual case, decided without any segment test
            }
        }
        List<Rect> near = new ArrayList<>(4);
        for (Rect surface : surfaces) {
            if (surface.touches(bounds)) {
                near.add(surface);
            }
        }
        return !near.isEmpty() && footprint.isCoveredBy(near);
    }

    /**
     * The lane pose at a point: the centre of the lane half holding it, at the same distance along
     * the road, facing that lane's legal direction. Empty off the road.
     */
    public Optional<StartPose> snapToLane(double x, double y) {
        Road road = roadAt(x, y);
        if (road == null) {
            return Optional.empty();
        }
        Compass heading = road.laneDirectionAt(x, y);
        Vec2 position = road.point(road.along(x, y), road.laneCentre(heading));
        return Optional.of(new StartPose(new Vec2(Dimensions.rounded(position.x()), Dimensions.rounded(position.y())), heading));
    }

    /** Where a parked car stands if left at the point: 0.325 m off the nearer kerb, along its road. */
    public static Vec2 kerbsidePosition(Road road, double x, double y) {
        double side = road.across(x, y) < road.centre() ? -1 : 1;
        double across = road.centre() + side * (HALF_ROAD - EDGE_LINE_OFFSET - EDGE_LINE_WIDTH - Dimensions.CAR_WIDTH / 2);
        Vec2 p = road.point(road.along(x, y), across);
        return new Vec2(Dimensions.rounded(p.x()), Dimensions.rounded(p.y()));
    }

    private List<Marking> markingsOf(Road road) {
        List<double[]> cuts = new ArrayList<>();
        for (Junction junction : junctions) {
            Rect square = junction.square();
            if (square.overlaps(road.surface())) {
                double c = road.along(junction.centre().x(), junction.centre().y());
                cuts.add(new double[] {c - HALF_ROAD, c + HALF_ROAD});
            }
        }
        cuts.sort(Comparator.comparingDouble(c -> c[0]));
        List<double[]> pieces = new ArrayList<>();
        double start = road.from();
        for (double[] cut : cuts) {
            if (cut[0] > start) {
                pieces.add(new double[] {start, Math.min(cut[0], road.to())});
            }
            start = Math.max(start, cut[1]);
        }
        if (start < road.to()) {
            pieces.add(new double[] {start, road.to()});
        }
        double near = HALF_ROAD - EDGE_LINE_OFFSET;
        double[][] lines = {
            {road.centre() - near, road.centre() - near + EDGE_LINE_WIDTH},
            {road.centre() - CENTRE_LINE_WIDTH / 2, road.centre() + CENTRE_LINE_WIDTH / 2},
            {road.centre() + near - EDGE_LINE_WIDTH, road.centre() + near},
        };
        List<Marking> result = new ArrayList<>();
        for (int i = 0; i < lines.length; i++) {
            MarkingKind kind = i == 1 ? MarkingKind.CENTRE : MarkingKind.EDGE;
            for (double[] piece : pieces) {
                Vec2 a = road.point(piece[0], lines[i][0]);
                Vec2 b = road.point(piece[1], lines[i][1]);
                result.add(new Marking(kind, road.id(), Rect.spanning(a.x(), a.y(), b.x(), b.y())));
            }
        }
        return result;
    }
}
