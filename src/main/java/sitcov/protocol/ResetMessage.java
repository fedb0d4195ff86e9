package sitcov.protocol;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import sitcov.control.RunStart;
import sitcov.faults.Fault;
import sitcov.geom.Vec2;
import sitcov.world.Axis;
import sitcov.world.Junction;
import sitcov.world.Layout;
import sitcov.world.Road;
import sitcov.world.StartPose;
import sitcov.world.Target;
import sitcov.world.WorldMap;

/**
 * The "reset" message that starts a run: the map as the controller may know it (roads, junctions,
 * Target, the car's start; no parked or moving cars, which it finds with its sensors), the internal
 * seed, and the faults of sitcov's catalogue switched on for the run.
 *
 * @param map          the map rebuilt from the message: a layout with no parked cars and no moving cars
 * @param internalSeed the run's internal seed
 * @param faults       the faults switched on
 */
record ResetMessage(WorldMap map, long internalSeed, Set<Fault> faults) {

    static void write(JsonWriter w, RunStart run, Set<Fault> faults) {
        write(w, run, faults, -1);
    }

    /** The reset of a run of a batch, tagged with its slot when {@code slot} is 0 or more. */
    static void write(JsonWriter w, RunStart run, Set<Fault> faults, int slot) {
        Layout layout = run.map().layout();
        w.reset().beginObject().member("type", "reset").name("map").beginObject().member("seed", layout.seed());
        w.name("roads").beginArray();
        for (Road r : layout.roads()) {
            w.beginObject().member("id", r.id()).member("axis", r.isNorthSouth() ? "north_south" : "east_west")
                    .member("centre", r.centre()).member("from", r.from()).member("to", r.to()).endObject();
        }
        w.endArray().name("junctions").beginArray();
        for (Junction j : layout.junctions()) {
            w.beginObject().member("id", j.id()).member("x", j.centre().x()).member("y", j.centre().y())
                    .name("arms").beginObject().member("north", j.armNorth()).member("east", j.armEast())
                    .member("south", j.armSouth()).member("west", j.armWest()).endObject().endObject();
        }
        w.endArray();
        Target target = layout.target().orElseThrow();
        w.name("target").beginObject().member("x", target.position().x()).member("y", target.position().y())
                .member("road", target.roadId()).endObject();
        StartPose start = layout.carStart().orElseThrow();
        w.name("start").beginObject().member("x", start.position().x()).member("y", start.position().y())
                .member("heading", start.heading().bearing()).endObject();
        w.endObject().member("internal_seed", run.internalSeed()).name("faults").beginArray();
        for (Fault f : faults) {
            w.value(f.id());
        }
        w.endArray();
        if (slot >= 0) {
            w.member("run", slot);
        }
        w.endObject();
    }

    static ResetMessage read(Message m) throws ProtocolException {
        m.expect("reset");
        Message map = m.object("map");
        List<Road> roads = new ArrayList<>();
        List<Object> roadItems = map.list("roads");
        for (int i = 0; i < roadItems.size(); i++) {
            Message r = map.item(roadItems, i, "roads");
            String axis = r.text("axis");
            if (!axis.equals("north_south") && !axis.equals("east_west")) {
                throw new ProtocolException("reset.map.roads[" + i + "].axis must be north_south or east_west");
            }
            try {
                roads.add(new Road((int) r.integer("id"), axis.equals("north_south") ? Axis.NORTH_SOUTH : Axis.EAST_WEST,
                        r.number("centre"), r.number("from"), r.number("to")));
            } catch (IllegalArgumentException bad) {
                throw new ProtocolException("reset.map.roads[" + i + "]: " + bad.getMessage());
            }
        }
        List<Junction> junctions = new ArrayList<>();
        List<Object> junctionItems = map.list("junctions");
        for (int i = 0; i < junctionItems.size(); i++) {
            Message j = map.item(junctionItems, i, "junctions");
            Message arms = j.object("arms");
            junctions.add(new Junction((int) j.integer("id"), new Vec2(j.number("x"), j.number("y")),
                    arms.number("north"), arms.number("east"), arms.number("south"), arms.number("west")));
        }
        Message t = map.object("target");
        Target target = new Target(new Vec2(t.number("x"), t.number("y")), (int) t.integer("road"));
        Message s = map.object("start");
        StartPose start;
        try {
            start = new StartPose(new Vec2(s.number("x"), s.number("y")),
                    sitcov.geom.Compass.ofBearing(s.number("heading")));
        } catch (IllegalArgumentException bad) {
            throw new ProtocolException("reset.map.start.heading: " + bad.getMessage());
        }
        Layout layout = new Layout(map.integer("seed"), roads, junctions, List.of(), Optional.of(target),
                Optional.of(start), 0, 0, List.of());
        Set<Fault> faults = EnumSet.noneOf(Fault.class);
        List<Object> ids = m.optionalList("faults");
        for (int i = 0; i < ids.size(); i++) {
            long id = m.wholeAt(ids, i, "faults");
            if (id < 0 || id >= Fault.values().length) {
                throw new ProtocolException("reset.faults: there is no fault " + id);
            }
            faults.add(Fault.ofId((int) id));
        }
        return new ResetMessage(new WorldMap(layout, List.of(), 0, List.of()), m.integer("internal_seed"), faults);
    }
}
