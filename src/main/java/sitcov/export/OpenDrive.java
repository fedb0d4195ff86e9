package sitcov.export;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.WorldMap;

/**
 * A map's roads as an ASAM OpenDRIVE document (src/main/java/sitcov/export/README.md, "Export to OpenDRIVE and
 * OpenSCENARIO"):
 * valid against the 1.7 schema and kept to what 1.4 readers understand — straight lines and arcs,
 * lanes of constant width, road and junction links; left-hand traffic ({@code rule="LHT"}), so a
 * road's lane 1 carries traffic along its reference line. Each T-junction is a junction with a
 * connecting road for every movement from one arm to another; dead ends are open road ends.
 */
public final class OpenDrive {
    /** A connecting road's reference line runs from centre line to centre line around the square's corner. */
    private static final double TURN_RADIUS = Dimensions.HALF_ROAD;

    private OpenDrive() {
    }

    /** A movement through a junction: in from one arm, out through another, along connecting road {@code id}. */
    record Movement(int id, Junction junction, Compass from, Compass to) {
        boolean isStraight() {
            return to == from.opposite();
        }

        /** +1 for a left (anticlockwise) turn, −1 for a right one, 0 straight on. */
        int turn() {
            Compass driving = from.opposite();
            // in the ASAM frame a compass direction is (dx, −dy): y points north
            long cross = (long) driving.dx() * -to.dy() - (long) -driving.dy() * to.dx();
            return Long.signum(cross);
        }

        double length() {
            return isStraight() ? 2 * Dimensions.HALF_ROAD : Math.PI / 2 * TURN_RADIUS;
        }
    }

    public static String document(WorldMap map) {
        Layout layout = map.layout();
        RoadPieces pieces = RoadPieces.of(layout);
        List<Movement> movements = movements(layout, pieces.pieces().size());
        Xml xml = new Xml();
        xml.open("OpenDRIVE");
        xml.empty("header", "revMajor", "1", "revMinor", "7", "name", "sitcov map " + map.seed(), "version", "1",
                "north", Xml.metres(Dimensions.WORLD_HEIGHT), "south", Xml.metres(0), "east",
                Xml.metres(Dimensions.WORLD_WIDTH), "west", Xml.metres(0), "vendor", "sitcov");
        for (RoadPieces.Piece piece : pieces.pieces()) {
            piece(xml, piece);
        }
        for (Movement m : movements) {
            connectingRoad(xml, m, pieces);
        }
        for (Junction j : layout.junctions()) {
            if (!j.isDeadEnd()) {
                junction(xml, j, movements, pieces);
            }
        }
        xml.close();
        return xml.document();
    }

    private static List<Movement> movements(Layout layout, int pieceCount) {
        List<Movement> movements = new ArrayList<>();
        for (Junction j : layout.junctions()) {
            if (j.isDeadEnd()) {
                continue;
            }
            for (Compass from : j.arms()) {
                for (Compass to : j.arms()) {
                    if (to != from) {
                        movements.add(new Movement(pieceCount + movements.size() + 1, j, from, to));
                    }
                }
            }
        }
        return movements;
    }

    private static void piece(Xml xml, RoadPieces.Piece piece) {
        xml.open("road", "name", "sitcov road " + piece.road().id(), "length", Xml.metres(piece.length()),
                "id", Integer.toString(piece.id()), "junction", "-1", "rule", "LHT");
        if (piece.atStart().isPresent() || piece.atEnd().isPresent()) {
            xml.open("link");
            piece.atStart().ifPresent(c -> junctionLink(xml, "predecessor", c.junction()));
            piece.atEnd().ifPresent(c -> junctionLink(xml, "successor", c.junction()));
            xml.close();
        }
        roadType(xml);
        Vec2 start = piece.road().point(piece.startAlong(), piece.road().centre());
        xml.open("planView");
        geometry(xml, start, piece.direction(), piece.length(), 0);
        xml.close();
        xml.open("lanes").open("laneSection", "s", Xml.metres(0));
        xml.open("left");
        lane(xml, 1, Optional.empty(), "solid");
        xml.close();
        centre(xml, "solid");
        xml.open("right");
        lane(xml, -1, Optional.empty(), "solid");
        xml.close();
        xml.close().close().close();
    }

    private static void connectingRoad(Xml xml, Movement m, RoadPieces pieces) {
        RoadPieces.Piece in = pieces.arm(m.junction(), m.from());
        RoadPieces.Piece out = pieces.arm(m.junction(), m.to());
        xml.open("road", "name", "sitcov junction " + m.junction().id() + " " + name(m.from()) + " to " + name(m.to()),
                "length", Xml.metres(m.length()), "id", Integer.toString(m.id()),
                "junction", Integer.toString(m.junction().id()), "rule", "LHT");
        xml.open("link");
        xml.empty("predecessor", "elementType", "road", "elementId", Integer.toString(in.id()),
                "contactPoint", in.contactPointAt(m.junction()));
        xml.empty("successor", "elementType", "road", "elementId", Integer.toString(out.id()),
                "contactPoint", out.contactPointAt(m.junction()));
        xml.close();
        roadType(xml);
        Vec2 centre = m.junction().centre();
        Vec2 start = new Vec2(centre.x() + m.from().dx() * Dimensions.HALF_ROAD,
                centre.y() + m.from().dy() * Dimensions.HALF_ROAD);
        xml.open("planView");
        geometry(xml, start, m.from().opposite(), m.length(), m.turn() / TURN_RADIUS);
        xml.close();
        xml.open("lanes").open("laneSection", "s", Xml.metres(0));
        xml.open("left");
        lane(xml, 1, Optional.of(new int[] {in.laneInto(m.junction()), out.laneOutOf(m.junction())}), "none");
        xml.close();
        centre(xml, "none");
        xml.close().close().close();
    }

    private static void junction(Xml xml, Junction j, List<Movement> movements, RoadPieces pieces) {
        xml.open("junction", "name", "sitcov junction " + j.id(), "id", Integer.toString(j.id()));
        int connection = 0;
        for (Movement m : movements) {
            if (m.junction() != j) {
                continue;
            }
            RoadPieces.Piece in = pieces.arm(j, m.from());
            xml.open("connection", "id", Integer.toString(connection++), "incomingRoad", Integer.toString(in.id()),
                    "connectingRoad", Integer.toString(m.id()), "contactPoint", "start");
            xml.empty("laneLink", "from", Integer.toString(in.laneInto(j)), "to", "1");
            xml.close();
        }
        xml.close();
    }

    private static void junctionLink(Xml xml, String which, Junction j) {
        xml.empty(which, "elementType", "junction", "elementId", Integer.toString(j.id()));
    }

    /** A town road with the car's top speed as its limit. */
    private static void roadType(Xml xml) {
        xml.open("type", "s", Xml.metres(0), "type", "town");
        xml.empty("speed", "max", "45", "unit", "km/h");
        xml.close();
    }

    private static void geometry(Xml xml, Vec2 start, Compass heading, double length, double curvature) {
        xml.open("geometry", "s", Xml.metres(0), "x", Xml.metres(AsamFrame.x(start.x())),
                "y", Xml.metres(AsamFrame.y(start.y())), "hdg", Xml.fine(AsamFrame.heading(heading.bearing())),
                "length", Xml.metres(length));
        if (curvature == 0) {
            xml.empty("line");
        } else {
            xml.empty("arc", "curvature", Xml.fine(curvature));
        }
        xml.close();
    }

    /** A 3 m driving lane; {@code links} its predecessor and successor lanes inside a junction. */
    private static void lane(Xml xml, int id, Optional<int[]> links, String mark) {
        xml.open("lane", "id", Integer.toString(id), "type", "driving", "level", "false");
        if (links.isPresent()) {
            xml.open("link");
            xml.empty("predecessor", "id", Integer.toString(links.get()[0]));
            xml.empty("successor", "id", Integer.toString(links.get()[1]));
            xml.close();
        }
        xml.empty("width", "sOffset", Xml.metres(0), "a", Xml.metres(Dimensions.LANE_WIDTH), "b", "0", "c", "0", "d", "0");
        xml.empty("roadMark", "sOffset", Xml.metres(0), "type", mark, "weight", "standard", "color", "standard",
                "width", Xml.metres(Dimensions.EDGE_LINE_WIDTH));
        xml.close();
    }

    /** The centre lane carries the centre line (none inside a junction, where sitcov paints none). */
    private static void centre(Xml xml, String mark) {
        xml.open("center");
        xml.open("lane", "id", "0", "type", "none", "level", "false");
        xml.empty("roadMark", "sOffset", Xml.metres(0), "type", mark, "weight", "standard", "color", "standard",
                "width", Xml.metres(Dimensions.CENTRE_LINE_WIDTH));
        xml.close().close();
    }

    private static String name(Compass c) {
        return c.name().toLowerCase(java.util.Locale.ROOT);
    }
}
