package sitcov.world;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import sitcov.geom.Compass;
import sitcov.geom.Vec2;

/** Reads the text of a situation file, line by line, refusing anything malformed with its line number. */
final class SituationParser {
    private final String source;
    private int lineNumber;
    private String[] words;

    private Long seed;
    private int[] generation;
    private final List<Road> roads = new ArrayList<>();
    private final List<Junction> junctions = new ArrayList<>();
    private final List<ParkedCar> parkedCars = new ArrayList<>();
    private Target target;
    private StartPose carStart;
    private final List<StartPose> movingCars = new ArrayList<>();
    private final List<Omission> layoutOmissions = new ArrayList<>();
    private final List<Omission> movingOmissions = new ArrayList<>();
    private final java.util.Map<Invariants.Element, List<Integer>> lines = new java.util.EnumMap<>(Invariants.Element.class);

    SituationParser(String source) {
        this.source = source;
    }

    WorldMap parse(List<String> lines) throws SituationFormatException {
        boolean headerSeen = false;
        boolean ended = false;
        for (int i = 0; i < lines.size(); i++) {
            lineNumber = i + 1;
            String raw = lines.get(i);
            // an editor's UTF-8 byte-order mark is no part of the text
            String text = (i == 0 && raw.startsWith("\uFEFF") ? raw.substring(1) : raw).strip();
            if (text.isEmpty() || text.startsWith("#")) {
                continue;
            }
            if (ended) {
                throw error("expected nothing after 'end', found '" + text + "'");
            }
            words = text.split("\\s+");
            if (!headerSeen) {
                header();
                headerSeen = true;
                continue;
            }
            switch (words[0]) {
                case "seed" -> seed();
                case "generation" -> generation();
                case "road" -> road();
                case "junction" -> junction();
                case "parked-car" -> parkedCar();
                case "target" -> target();
                case "car-start" -> carStart();
                case "moving-car" -> movingCar();
                case "omission" -> omission(text);
                case "end" -> {
                    arity(1, "end");
                    ended = true;
                }
                default -> throw error("expected one of seed, generation, road, junction, parked-car, target, "
                        + "car-start, moving-car, omission, end; found '" + words[0] + "'");
            }
        }
        lineNumber = 0;
        if (!headerSeen) {
            throw error("empty file: expected a first line '" + SituationFile.MAGIC + " " + SituationFile.VERSION + "'");
        }
        if (!ended) {
            throw error("the file ends without its closing 'end' line (was it cut short?)");
        }
        return build();
    }

    private void header() throws SituationFormatException {
        if (!words[0].equals(SituationFile.MAGIC) || words.length != 2) {
            throw error("expected the first line '" + SituationFile.MAGIC + " " + SituationFile.VERSION
                    + "' (is this a sitcov situation file?)");
        }
        if (!words[1].equals(String.valueOf(SituationFile.VERSION))) {
            throw error("situation file version " + words[1] + " is not supported; this sitcov reads version "
                    + SituationFile.VERSION);
        }
    }

    private void seed() throws SituationFormatException {
        arity(2, "seed SEED");
        once(seed, "seed");
        seed = whole(1, "SEED");
    }

    private void generation() throws SituationFormatException {
        arity(4, "generation JUNCTION_ATTEMPTS PARKED_CARS_REQUESTED MOVING_CARS_REQUESTED");
        once(generation, "generation");
        generation = new int[] {count(1, "JUNCTION_ATTEMPTS"), count(2, "PARKED_CARS_REQUESTED"),
            count(3, "MOVING_CARS_REQUESTED")};
    }

    private void road() throws SituationFormatException {
        arity(6, "road ID AXIS CENTRE FROM TO");
        cap(Invariants.Element.ROAD, roads.size(), SituationFile.MAX_ROADS, "roads");
        int id = id(1, roads.size(), "road");
        Axis axis = axis(2);
        double from = number(4, "FROM");
        double to = number(5, "TO");
        if (!(from < to)) {
            throw error("expected FROM < TO for road " + id + ", found " + from + " and " + to);
        }
        roads.add(new Road(id, axis, number(3, "CENTRE"), from, to));
    }

    private void junction() throws SituationFormatException {
        arity(8, "junction ID X Y ARM_NORTH ARM_EAST ARM_SOUTH ARM_WEST");
        cap(Invariants.Element.JUNCTION, junctions.size(), SituationFile.MAX_JUNCTIONS, "junctions");
        int id = id(1, junctions.size(), "junction");
        Vec2 centre = point(2);
        double[] arms = new double[4];
        for (int k = 0; k < 4; k++) {
            arms[k] = number(4 + k, "an arm length");
            if (arms[k] < 0) {
                throw error("expected arm lengths of 0 or more, found " + arms[k]);
            }
        }
        junctions.add(new Junction(id, centre, arms[0], arms[1], arms[2], arms[3]));
    }

    private void parkedCar() throws SituationFormatException {
        arity(6, "parked-car ID ROAD_ID X Y AXIS");
        cap(Invariants.Element.PARKED_CAR, parkedCars.size(), SituationFile.MAX_CARS, "parked cars");
        int id = id(1, parkedCars.size(), "parked-car");
        parkedCars.add(new ParkedCar(id, roadId(2), point(3), axis(5)));
    }

    private void target() throws SituationFormatException {
        arity(4, "target X Y ROAD_ID");
        once(target, "target");
        cap(Invariants.Element.TARGET, 0, 1, "targets");
        target = new Target(point(1), roadId(3));
    }

    private void carStart() throws SituationFormatException {
        arity(4, "car-start X Y HEADING");
        once(carStart, "car-start");
        cap(Invariants.Element.CAR_START, 0, 1, "car starts");
        carStart = new StartPose(point(1), heading(3));
    }

    private void movingCar() throws SituationFormatException {
        arity(4, "moving-car X Y HEADING");
        cap(Invariants.Element.MOVING_CAR, movingCars.size(), SituationFile.MAX_CARS, "moving cars");
        movingCars.add(new StartPose(point(1), heading(3)));
    }

    private void omission(String text) throws SituationFormatException {
        String rest = text.substring("omission".length()).strip();
        int space = rest.indexOf(' ');
        int colon = rest.indexOf(": ");
        if (space < 0 || colon < space) {
            throw error("expected 'omission layout|moving-cars ELEMENT: REASON'");
        }
        String part = rest.substring(0, space);
        Omission omission = new Omission(rest.substring(space + 1, colon).strip(), rest.substring(colon + 2).strip());
        switch (part) {
            case "layout" -> layoutOmissions.add(omission);
            case "moving-cars" -> movingOmissions.add(omission);
            default -> throw error("expected 'layout' or 'moving-cars' after 'omission', found '" + part + "'");
        }
    }

    private WorldMap build() throws SituationFormatException {
        if (seed == null) {
            throw error("no 'seed' line: expected 'seed SEED'");
        }
        if (roads.isEmpty()) {
            throw error("no 'road' line: a situation needs at least one road");
        }
        int[] g = generation == null ? new int[] {0, parkedCars.size(), movingCars.size()} : generation;
        Layout layout = new Layout(seed, roads, junctions, parkedCars, Optional.ofNullable(target),
                Optional.ofNullable(carStart), g[0], g[1], layoutOmissions);
        WorldMap map = new WorldMap(layout, movingCars, g[2], movingOmissions);
        List<Invariants.Violation> broken = Invariants.check(map);
        if (!broken.isEmpty()) {
            Invariants.Violation first = broken.get(0);
            List<Integer> at = lines.getOrDefault(first.element(), List.of());
            lineNumber = first.element() == Invariants.Element.NETWORK ? lines.get(Invariants.Element.ROAD).get(0)
                    : first.index() < at.size() ? at.get(first.index()) : 0;
            throw error("breaks a rule of the world: " + first.rule()
                    + (broken.size() > 1 ? " (and " + (broken.size() - 1) + " more rule" + (broken.size() > 2 ? "s" : "")
                    + " broken)" : ""));
        }
        return map;
    }

    /** Notes the line of the next element of a kind, refusing more than a situation can hold. */
    private void cap(Invariants.Element element, int count, int max, String what) throws SituationFormatException {
        if (count >= max) {
            throw error("more than " + max + " " + what + ": a situation holds at most " + max);
        }
        lines.computeIfAbsent(element, e -> new ArrayList<>()).add(lineNumber);
    }

    private int roadId(int index) throws SituationFormatException {
        int id = count(index, "ROAD_ID");
        if (id >= roads.size()) {
            throw error("expected the id of a road listed above (0 to " + (roads.size() - 1) + "), found " + id);
        }
        return id;
    }

    private int id(int index, int expected, String what) throws SituationFormatException {
        int id = count(index, "ID");
        if (id != expected) {
            throw error("expected " + what + " id " + expected + " (ids count up from 0 in file order), found " + id);
        }
        return id;
    }

    private Vec2 point(int index) throws SituationFormatException {
        return new Vec2(number(index, "X"), number(index + 1, "Y"));
    }

    private Axis axis(int index) throws SituationFormatException {
        try {
            return Axis.valueOf(words[index]);
        } catch (IllegalArgumentException e) {
            throw error("expected an axis NORTH_SOUTH or EAST_WEST, found '" + words[index] + "'");
        }
    }

    private Compass heading(int index) throws SituationFormatException {
        try {
            return Compass.valueOf(words[index]);
        } catch (IllegalArgumentException e) {
            throw error("expected a heading NORTH, EAST, SOUTH or WEST, found '" + words[index] + "'");
        }
    }

    private double number(int index, String what) throws SituationFormatException {
        try {
            double v = Double.parseDouble(words[index]);
            if (Math.abs(v) <= SituationFile.MAX_COORDINATE) {
                return v;
            }
            throw error("expected a number for " + what + " within " + (long) SituationFile.MAX_COORDINATE
                    + " m of the origin (the world is " + Dimensions.WORLD_WIDTH + " x " + Dimensions.WORLD_HEIGHT
                    + " m), found '" + words[index] + "'");
        } catch (NumberFormatException e) {
            // reported below
        }
        throw error("expected a number for " + what + ", found '" + words[index] + "'");
    }

    private long whole(int index, String what) throws SituationFormatException {
        try {
            return Long.parseLong(words[index]);
        } catch (NumberFormatException e) {
            throw error("expected a whole number for " + what + ", found '" + words[index] + "'");
        }
    }

    private int count(int index, String what) throws SituationFormatException {
        long v = whole(index, what);
        if (v < 0 || v > Integer.MAX_VALUE) {
            throw error("expected a count of 0 or more for " + what + ", found " + v);
        }
        return (int) v;
    }

    private void arity(int n, String form) throws SituationFormatException {
        if (words.length != n) {
            throw error("expected '" + form + "' (" + n + " words), found " + words.length + " words");
        }
    }

    private void once(Object existing, String keyword) throws SituationFormatException {
        if (existing != null) {
            throw error("a second '" + keyword + "' line: expected it once");
        }
    }

    private SituationFormatException error(String problem) {
        return new SituationFormatException(source, lineNumber, problem);
    }
}
