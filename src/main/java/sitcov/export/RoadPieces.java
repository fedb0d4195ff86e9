package sitcov.export;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import sitcov.geom.Compass;
import sitcov.world.Dimensions;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.Road;

/**
 * A map's roads as OpenDRIVE sees them: every road cut at each T-junction's square into pieces,
 * each piece a road of its own whose reference line is the centre line, pointing east on an
 * east–west road and north on a north–south one. A piece's ends either meet a T-junction through
 * one of its arms or are open (a dead end is just road that stops).
 */
final class RoadPieces {
    /** Pieces shorter than this are the touching edges of two squares, not road. */
    private static final double NO_LENGTH = 1e-6;

    /** Where a piece's end meets a T-junction: the junction and the arm it is. */
    record Contact(Junction junction, Compass arm) {
    }

    /**
     * A piece of {@code road} between {@code from} and {@code to} along it (sitcov's along
     * coordinate), numbered {@code id} in the OpenDRIVE file.
     */
    record Piece(int id, Road road, double from, double to, Optional<Contact> atStart, Optional<Contact> atEnd) {
        double length() {
            return to - from;
        }

        /** The along coordinate where the reference line starts: the west end, or the south end (largest y). */
        double startAlong() {
            return road.isNorthSouth() ? to : from;
        }

        /** The direction the reference line points. */
        Compass direction() {
            return road.isNorthSouth() ? Compass.NORTH : Compass.EAST;
        }

        /** The contact at the junction {@code j}, as OpenDRIVE names the piece's end there. */
        String contactPointAt(Junction j) {
            return atStart.filter(c -> c.junction().equals(j)).isPresent() ? "start" : "end";
        }

        /** The lane that drives towards the junction at that end: lane 1 drives along the reference line. */
        int laneInto(Junction j) {
            return contactPointAt(j).equals("end") ? 1 : -1;
        }

        int laneOutOf(Junction j) {
            return -laneInto(j);
        }
    }

    private final List<Piece> pieces;

    private RoadPieces(List<Piece> pieces) {
        this.pieces = List.copyOf(pieces);
    }

    static RoadPieces of(Layout layout) {
        List<Junction> tJunctions = layout.junctions().stream().filter(j -> !j.isDeadEnd()).toList();
        List<Piece> pieces = new ArrayList<>();
        for (Road road : layout.roads()) {
            List<Junction> on = tJunctions.stream().filter(j -> road.carries(j.centre()))
                    .sorted(Comparator.comparingDouble(j -> road.along(j.centre().x(), j.centre().y()))).toList();
            double start = road.from();
            Optional<Junction> before = Optional.empty();
            for (Junction j : on) {
                double centre = road.along(j.centre().x(), j.centre().y());
                add(pieces, road, start, centre - Dimensions.HALF_ROAD, before, Optional.of(j));
                start = centre + Dimensions.HALF_ROAD;
                before = Optional.of(j);
            }
            add(pieces, road, start, road.to(), before, Optional.empty());
        }
        return new RoadPieces(pieces);
    }

    /** Adds the piece between {@code from} and {@code to}, with the junctions at its smaller and larger end. */
    private static void add(List<Piece> pieces, Road road, double from, double to, Optional<Junction> atFrom,
                            Optional<Junction> atTo) {
        if (to - from < NO_LENGTH) {
            return;
        }
        // the arm a piece is, seen from the junction: the piece lies towards larger along beyond `atFrom`
        Compass larger = road.isNorthSouth() ? Compass.SOUTH : Compass.EAST;
        Optional<Contact> fromContact = atFrom.map(j -> new Contact(j, larger));
        Optional<Contact> toContact = atTo.map(j -> new Contact(j, larger.opposite()));
        boolean startsAtFrom = !road.isNorthSouth();
        pieces.add(new Piece(pieces.size() + 1, road, from, to, startsAtFrom ? fromContact : toContact,
                startsAtFrom ? toContact : fromContact));
    }

    List<Piece> pieces() {
        return pieces;
    }

    /** The piece that is arm {@code arm} of {@code junction}. */
    Piece arm(Junction junction, Compass arm) {
        for (Piece p : pieces) {
            for (Optional<Contact> c : List.of(p.atStart(), p.atEnd())) {
                if (c.isPresent() && c.get().junction().equals(junction) && c.get().arm() == arm) {
                    return p;
                }
            }
        }
        throw new IllegalStateException("junction " + junction.id() + " has no road between its square and the next on its "
                + arm + " arm, and OpenDRIVE joins junctions only by roads");
    }
}
