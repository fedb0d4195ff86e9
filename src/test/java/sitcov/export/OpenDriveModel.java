package sitcov.export;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.w3c.dom.Element;
import sitcov.geom.Vec2;

/**
 * An OpenDRIVE document read back with the DOM parser and evaluated as ASAM OpenDRIVE 1.7 defines it,
 * independently of the export: a road's reference line is its plan view's geometries (line and arc),
 * a lane's centre lies off the reference line along its left normal (t, left positive) by the lane offset
 * plus the widths of the lanes between it and the centre lane, and under {@code rule="LHT"} the left lanes
 * (positive ids) drive along the reference line, under RHT (the default) the right ones.
 */
record OpenDriveModel(Map<String, Road> roads, Map<String, Junction> junctions) {

    static OpenDriveModel parse(String xml) {
        Element root = Dom.parse(xml);
        if (!root.getTagName().equals("OpenDRIVE")) {
            throw new AssertionError("the root element is <" + root.getTagName() + ">, not <OpenDRIVE>");
        }
        List<Road> roads = Dom.children(root, "road").stream().map(OpenDriveModel::road).toList();
        List<Junction> junctions = Dom.children(root, "junction").stream().map(OpenDriveModel::junction).toList();
        return new OpenDriveModel(byId(roads, Road::id), byId(junctions, Junction::id));
    }

    /** The ordinary roads (not inside a junction). */
    List<Road> pieces() {
        return roads.values().stream().filter(r -> r.junction().equals("-1")).toList();
    }

    List<Road> connectingRoads(String junctionId) {
        return roads.values().stream().filter(r -> r.junction().equals(junctionId)).toList();
    }

    record Road(String id, String junction, double length, boolean leftHandTraffic, Optional<Link> predecessor,
                Optional<Link> successor, List<Geometry> geometry, List<Offset> laneOffsets, List<Lane> lanes) {
        Vec2 start() {
            return point(0, 0);
        }

        Vec2 end() {
            return point(length, 0);
        }

        /** The point {@code t} metres left of the reference line at {@code s}. */
        Vec2 point(double s, double t) {
            Geometry g = geometryAt(s);
            return g.point(s - g.s(), t);
        }

        double heading(double s) {
            Geometry g = geometryAt(s);
            return g.heading(s - g.s());
        }

        Geometry geometryAt(double s) {
            Geometry at = geometry.get(0);
            for (Geometry g : geometry) {
                if (g.s() <= s + 1e-9) {
                    at = g;
                }
            }
            return at;
        }

        Optional<Lane> lane(int id) {
            return lanes.stream().filter(l -> l.id() == id).findFirst();
        }

        /** The t of lane {@code id}'s centre at {@code s}: the offset plus the widths of the lanes inside it, plus half its own. */
        double laneCentre(int id, double s) {
            if (id == 0) {
                throw new IllegalArgumentException("lane 0 is the reference line, it has no width");
            }
            double t = 0;
            for (Offset o : laneOffsets) {
                if (o.s() <= s + 1e-9) {
                    t = o.at(s - o.s());
                }
            }
            int sign = Integer.signum(id);
            for (int k = sign; k != id; k += sign) {
                t += sign * width(k, s);
            }
            return t + sign * width(id, s) / 2;
        }

        private double width(int id, double s) {
            Lane lane = lane(id).orElseThrow(() -> new AssertionError("road " + this.id + " has no lane " + id));
            Offset w = null;
            for (Offset o : lane.widths()) {
                if (o.s() <= s + 1e-9) {
                    w = o;
                }
            }
            if (w == null) {
                throw new AssertionError("road " + this.id + " lane " + id + " has no <width> at s=" + s);
            }
            return w.at(s - w.s());
        }

        /** Whether lane {@code id} is driven along the reference line (the traffic rule decides which side does). */
        boolean drivenAlongReference(int id) {
            return (id > 0) == leftHandTraffic;
        }

        /** The unit vector lane {@code id} is driven along at {@code s}. */
        Vec2 drivingDirection(int id, double s) {
            Vec2 along = Frame.unit(heading(s));
            return drivenAlongReference(id) ? along : along.times(-1);
        }
    }

    /** One plan-view record: a line ({@code curvature} 0) or an arc. */
    record Geometry(double s, double x, double y, double hdg, double length, String kind, double curvature) {
        boolean isLine() {
            return kind.equals("line");
        }

        double heading(double ds) {
            return hdg + curvature * ds;
        }

        /** The point {@code ds} along and {@code t} left of this record's reference line. */
        Vec2 point(double ds, double t) {
            double x0;
            double y0;
            if (curvature == 0) {
                x0 = x + ds * Math.cos(hdg);
                y0 = y + ds * Math.sin(hdg);
            } else {
                // the arc about its centre, 1/curvature to the left of the start (to the right when negative)
                x0 = x + (Math.sin(hdg + curvature * ds) - Math.sin(hdg)) / curvature;
                y0 = y - (Math.cos(hdg + curvature * ds) - Math.cos(hdg)) / curvature;
            }
            double h = heading(ds);
            return new Vec2(x0 - t * Math.sin(h), y0 + t * Math.cos(h));
        }

        /** The (ds, t) of {@code p} against this record's reference line: along it from the start, and left of it. */
        double[] locate(Vec2 p) {
            if (curvature == 0) {
                double dx = p.x() - x;
                double dy = p.y() - y;
                return new double[] {dx * Math.cos(hdg) + dy * Math.sin(hdg), -dx * Math.sin(hdg) + dy * Math.cos(hdg)};
            }
            double r = 1 / Math.abs(curvature);
            double side = Math.signum(curvature);
            Vec2 centre = new Vec2(x - side * r * Math.sin(hdg), y + side * r * Math.cos(hdg));
            double start = Math.atan2(y - centre.y(), x - centre.x());
            double at = Math.atan2(p.y() - centre.y(), p.x() - centre.x());
            double swept = side * (at - start);
            swept = swept - 2 * Math.PI * Math.floor(swept / (2 * Math.PI));
            double fromCentre = p.distanceTo(centre);
            return new double[] {swept * r, side * (r - fromCentre)};
        }
    }

    /** A cubic a + b·ds + c·ds² + d·ds³ from {@code s} on: a lane width, or the lane offset. */
    record Offset(double s, double a, double b, double c, double d) {
        double at(double ds) {
            return a + ds * (b + ds * (c + ds * d));
        }
    }

    record Lane(int id, String type, Optional<Integer> predecessor, Optional<Integer> successor, List<Offset> widths) {
    }

    record Link(String elementType, String elementId, Optional<String> contactPoint) {
    }

    record Junction(String id, List<Connection> connections) {
    }

    record Connection(String id, String incomingRoad, String connectingRoad, String contactPoint, List<int[]> laneLinks) {
    }

    private static Road road(Element e) {
        Optional<Element> link = Dom.optionalChild(e, "link");
        List<Geometry> geometry = Dom.children(Dom.child(e, "planView"), "geometry").stream()
                .map(OpenDriveModel::geometry).toList();
        if (geometry.isEmpty()) {
            throw new AssertionError("road " + e.getAttribute("id") + " has no geometry");
        }
        Element lanes = Dom.child(e, "lanes");
        List<Element> sections = Dom.children(lanes, "laneSection");
        if (sections.size() != 1) {
            // the conventions give every road one lane section; reading more would only hide a difference
            throw new AssertionError("road " + e.getAttribute("id") + " has " + sections.size() + " lane sections, expected 1");
        }
        List<Lane> laneList = new ArrayList<>();
        for (String side : List.of("left", "right")) {
            Dom.optionalChild(sections.get(0), side).ifPresent(s ->
                    Dom.children(s, "lane").forEach(l -> laneList.add(lane(l))));
        }
        return new Road(Dom.text(e, "id"), Dom.text(e, "junction"), Dom.number(e, "length"),
                e.getAttribute("rule").equals("LHT"),
                link.flatMap(l -> Dom.optionalChild(l, "predecessor")).map(OpenDriveModel::link),
                link.flatMap(l -> Dom.optionalChild(l, "successor")).map(OpenDriveModel::link),
                geometry, Dom.children(lanes, "laneOffset").stream().map(OpenDriveModel::offset).toList(), laneList);
    }

    private static Geometry geometry(Element g) {
        Optional<Element> line = Dom.optionalChild(g, "line");
        Optional<Element> arc = Dom.optionalChild(g, "arc");
        if (line.isPresent() == arc.isPresent()) {
            throw new AssertionError("a <geometry> at s=" + g.getAttribute("s") + " is neither one <line> nor one <arc>");
        }
        return new Geometry(Dom.number(g, "s"), Dom.number(g, "x"), Dom.number(g, "y"), Dom.number(g, "hdg"),
                Dom.number(g, "length"), line.isPresent() ? "line" : "arc",
                arc.map(a -> Dom.number(a, "curvature")).orElse(0.0));
    }

    private static Lane lane(Element l) {
        Optional<Element> link = Dom.optionalChild(l, "link");
        return new Lane(Integer.parseInt(Dom.text(l, "id")), l.getAttribute("type"),
                link.flatMap(k -> Dom.optionalChild(k, "predecessor")).map(p -> Integer.parseInt(Dom.text(p, "id"))),
                link.flatMap(k -> Dom.optionalChild(k, "successor")).map(p -> Integer.parseInt(Dom.text(p, "id"))),
                Dom.children(l, "width").stream().map(OpenDriveModel::offset).toList());
    }

    private static Offset offset(Element w) {
        return new Offset(Dom.number(w, w.hasAttribute("sOffset") ? "sOffset" : "s"), Dom.number(w, "a"),
                Dom.number(w, "b"), Dom.number(w, "c"), Dom.number(w, "d"));
    }

    private static Link link(Element l) {
        return new Link(Dom.text(l, "elementType"), Dom.text(l, "elementId"),
                l.hasAttribute("contactPoint") ? Optional.of(l.getAttribute("contactPoint")) : Optional.empty());
    }

    private static Junction junction(Element j) {
        List<Connection> connections = Dom.children(j, "connection").stream().map(c -> new Connection(
                Dom.text(c, "id"), Dom.text(c, "incomingRoad"), Dom.text(c, "connectingRoad"), Dom.text(c, "contactPoint"),
                Dom.children(c, "laneLink").stream()
                        .map(k -> new int[] {Integer.parseInt(Dom.text(k, "from")), Integer.parseInt(Dom.text(k, "to"))})
                        .toList())).toList();
        return new Junction(Dom.text(j, "id"), connections);
    }

    private static <T> Map<String, T> byId(List<T> items, Function<T, String> id) {
        return items.stream().collect(Collectors.toMap(id, t -> t, (a, b) -> {
            throw new AssertionError("two elements share the id " + id.apply(a));
        }, java.util.LinkedHashMap::new));
    }
}
