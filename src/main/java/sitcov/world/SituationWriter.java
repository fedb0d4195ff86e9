package sitcov.world;

/** Writes the text of a situation file (see {@link SituationFile} for the format). */
final class SituationWriter {
    private SituationWriter() {
    }

    static String format(WorldMap map) {
        Layout layout = map.layout();
        StringBuilder out = new StringBuilder();
        out.append(SituationFile.MAGIC).append(' ').append(SituationFile.VERSION).append('\n');
        out.append("# A sitcov situation: metres, y grows southwards, bearings 0=S 90=E 180=N 270=W.\n");
        line(out, "seed", layout.seed());
        line(out, "generation", layout.junctionAttempts(), layout.parkedCarsRequested(), map.movingCarsRequested());
        out.append("# road ID AXIS CENTRE FROM TO\n");
        for (Road r : layout.roads()) {
            line(out, "road", r.id(), r.axis(), r.centre(), r.from(), r.to());
        }
        out.append("# junction ID X Y ARM_NORTH ARM_EAST ARM_SOUTH ARM_WEST\n");
        for (Junction j : layout.junctions()) {
            line(out, "junction", j.id(), j.centre().x(), j.centre().y(), j.armNorth(), j.armEast(), j.armSouth(), j.armWest());
        }
        out.append("# parked-car ID ROAD_ID X Y AXIS\n");
        for (ParkedCar p : layout.parkedCars()) {
            line(out, "parked-car", p.id(), p.roadId(), p.centre().x(), p.centre().y(), p.axis());
        }
        layout.target().ifPresent(t -> line(out, "target", t.position().x(), t.position().y(), t.roadId()));
        layout.carStart().ifPresent(s -> line(out, "car-start", s.position().x(), s.position().y(), s.heading()));
        for (StartPose s : map.movingCars()) {
            line(out, "moving-car", s.position().x(), s.position().y(), s.heading());
        }
        for (Omission o : layout.omissions()) {
            line(out, "omission", "layout", o);
        }
        for (Omission o : map.movingCarOmissions()) {
            line(out, "omission", "moving-cars", o);
        }
        out.append("end\n");
        return out.toString();
    }

    private static void line(StringBuilder out, String keyword, Object... values) {
        out.append(keyword);
        for (Object value : values) {
            out.append(' ').append(value);
        }
        out.append('\n');
    }
}
