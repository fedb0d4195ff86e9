package sitcov.export;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.w3c.dom.Element;

/**
 * An OpenSCENARIO document read back with the DOM parser: what the tests compare with sitcov — the header's
 * version, the road file, each entity's bounding box and properties, its Init position and speed, the timed
 * trajectory it follows (vertex times through the trajectory's Timing when it has one), the positions the ego is
 * sent to (a position to acquire, or a route's waypoints), where the scenario stops, the parameters and variables,
 * each event of the story: whose it is, when it starts, where it teleports and what it follows, and the events a
 * player reports an accident or a contact by.
 */
record ScenarioModel(int revMajor, int revMinor, String logicFile, Map<String, Box> entities,
                     Map<String, Map<String, String>> properties, Map<String, Pose> initial,
                     Map<String, Double> initialSpeed, List<Event> events, List<Pose> acquiredPositions,
                     List<Pose> routeWaypoints, List<Pose> reachConditions, Map<String, String> parameters,
                     Map<String, String> variables, List<Reported> reported) {

    /**
     * A WorldPosition, and the time of its vertex when it is one (NaN otherwise). A vehicle's poses are
     * read as a player reads them: its reference point moved by its bounding box's centre, so that
     * (x, y) is the centre of its footprint.
     */
    record Pose(double time, double x, double y, double h) {
    }

    record Box(double centreX, double centreY, double length, double width) {
    }

    /** An event of an entity's maneuver: its start time (NaN without a time condition), its teleports and its trajectories. */
    record Event(String entity, String name, double time, List<Pose> teleports, List<List<Pose>> trajectories) {
    }

    /**
     * An event that sets a variable (a parameter before 1.2) to true when a player sees what it declares: its
     * variable, its name, when it may start at the earliest, and the two vehicles whose touching starts it (empty
     * when only the time does).
     */
    record Reported(String variable, String name, double time, List<String> touching) {
    }

    List<Event> eventsOf(String entity) {
        return events.stream().filter(e -> e.entity().equals(entity)).toList();
    }

    static ScenarioModel parse(String xml) {
        Element root = Dom.parse(xml);
        if (!root.getTagName().equals("OpenSCENARIO")) {
            throw new AssertionError("the root element is <" + root.getTagName() + ">, not <OpenSCENARIO>");
        }
        Element header = Dom.child(root, "FileHeader");
        Element logic = Dom.child(Dom.child(root, "RoadNetwork"), "LogicFile");
        Map<String, Box> entities = new LinkedHashMap<>();
        Map<String, Map<String, String>> properties = new LinkedHashMap<>();
        for (Element o : Dom.children(Dom.child(root, "Entities"), "ScenarioObject")) {
            Map<String, String> own = new LinkedHashMap<>();
            Dom.descendants(o, "Property").forEach(p -> put(own, Dom.text(p, "name"), Dom.text(p, "value")));
            properties.put(Dom.text(o, "name"), own);
            Element box = Dom.child(Dom.child(o, "Vehicle"), "BoundingBox");
            Element c = Dom.child(box, "Center");
            Element d = Dom.child(box, "Dimensions");
            put(entities, Dom.text(o, "name"), new Box(Dom.number(c, "x"), Dom.number(c, "y"),
                    Dom.number(d, "length"), Dom.number(d, "width")));
        }
        Element storyboard = Dom.child(root, "Storyboard");
        Map<String, Pose> initial = new LinkedHashMap<>();
        Map<String, Double> speeds = new LinkedHashMap<>();
        for (Element p : Dom.children(Dom.child(Dom.child(storyboard, "Init"), "Actions"), "Private")) {
            String entity = Dom.text(p, "entityRef");
            for (Element t : Dom.descendants(p, "TeleportAction")) {
                put(initial, entity, centred(pose(Dom.child(Dom.child(t, "Position"), "WorldPosition"), Double.NaN),
                        entities.get(entity)));
            }
            for (Element s : Dom.descendants(p, "AbsoluteTargetSpeed")) {
                put(speeds, entity, Dom.number(s, "value"));
            }
        }
        List<Event> events = new ArrayList<>();
        List<Reported> reported = new ArrayList<>();
        for (Element event : Dom.descendants(storyboard, "Event")) {
            reported(event).ifPresent(reported::add);
            List<Element> time = Dom.descendants(Dom.child(event, "StartTrigger"), "SimulationTimeCondition");
            String actor = actor(event);
            Box box = entities.get(actor);
            events.add(new Event(actor, Dom.text(event, "name"),
                    time.isEmpty() ? Double.NaN : Dom.number(time.get(0), "value"),
                    Dom.descendants(event, "TeleportAction").stream()
                            .map(t -> centred(pose(Dom.child(Dom.child(t, "Position"), "WorldPosition"), Double.NaN), box))
                            .toList(),
                    Dom.descendants(event, "FollowTrajectoryAction").stream()
                            .map(f -> vertices(f).stream().map(v -> centred(v, box)).toList()).toList()));
        }
        Map<String, String> parameters = new LinkedHashMap<>();
        Dom.optionalChild(root, "ParameterDeclarations").ifPresent(ps -> Dom.children(ps, "ParameterDeclaration")
                .forEach(p -> put(parameters, Dom.text(p, "name"), Dom.text(p, "value"))));
        Map<String, String> variables = new LinkedHashMap<>();
        Dom.optionalChild(root, "VariableDeclarations").ifPresent(vs -> Dom.children(vs, "VariableDeclaration")
                .forEach(v -> put(variables, Dom.text(v, "name"), Dom.text(v, "value"))));
        List<Pose> reach = new ArrayList<>(positionsIn(storyboard, "ReachPositionCondition"));
        reach.addAll(positionsIn(storyboard, "DistanceCondition"));
        return new ScenarioModel((int) Dom.number(header, "revMajor"), (int) Dom.number(header, "revMinor"),
                Dom.text(logic, "filepath"), entities, properties, initial, speeds, events,
                positionsIn(storyboard, "AcquirePositionAction"), positionsIn(storyboard, "Waypoint"), reach,
                parameters, variables, reported);
    }

    /** The event as a report of an accident or a contact, when it sets a variable or a parameter to true. */
    private static java.util.Optional<Reported> reported(Element event) {
        List<Element> sets = new ArrayList<>(Dom.descendants(event, "VariableAction"));
        sets.addAll(Dom.descendants(event, "ParameterAction"));
        if (sets.isEmpty()) {
            return java.util.Optional.empty();
        }
        Element set = sets.get(0);
        String variable = set.hasAttribute("variableRef") ? Dom.text(set, "variableRef") : Dom.text(set, "parameterRef");
        if (!Dom.text(Dom.child(set, "SetAction"), "value").equals("true")) {
            throw new AssertionError(Dom.describe(event) + " sets " + variable + " to something other than true");
        }
        Element trigger = Dom.child(event, "StartTrigger");
        List<String> touching = new ArrayList<>();
        for (Element c : Dom.descendants(trigger, "CollisionCondition")) {
            Element byEntity = Dom.ancestor(c, "ByEntityCondition").orElseThrow();
            Dom.descendants(Dom.child(byEntity, "TriggeringEntities"), "EntityRef")
                    .forEach(r -> touching.add(Dom.text(r, "entityRef")));
            touching.add(Dom.text(Dom.child(c, "EntityRef"), "entityRef"));
        }
        List<Element> time = Dom.descendants(trigger, "SimulationTimeCondition");
        return java.util.Optional.of(new Reported(variable, Dom.text(event, "name"),
                time.isEmpty() ? Double.NaN : Dom.number(time.get(0), "value"), touching));
    }

    /** The entity an event moves: its ManeuverGroup's one actor. */
    private static String actor(Element event) {
        Element group = Dom.ancestor(event, "ManeuverGroup")
                .orElseThrow(() -> new AssertionError(Dom.describe(event) + " belongs to no ManeuverGroup"));
        List<Element> refs = Dom.children(Dom.child(group, "Actors"), "EntityRef");
        if (refs.size() != 1) {
            throw new AssertionError(Dom.describe(group) + " has " + refs.size() + " actors, expected the one that follows its trajectory");
        }
        return Dom.text(refs.get(0), "entityRef");
    }

    /** The trajectory's vertices, their times made absolute by its Timing (1.1 on; 1.0 has none and means them as given). */
    private static List<Pose> vertices(Element follow) {
        double scale = 1;
        double offset = 0;
        List<Element> timing = Dom.descendants(follow, "Timing");
        if (!timing.isEmpty()) {
            scale = Dom.number(timing.get(0), "scale");
            offset = Dom.number(timing.get(0), "offset");
        }
        List<Pose> out = new ArrayList<>();
        for (Element v : Dom.descendants(follow, "Vertex")) {
            out.add(pose(Dom.child(Dom.child(v, "Position"), "WorldPosition"), Dom.number(v, "time") * scale + offset));
        }
        return out;
    }

    private static List<Pose> positionsIn(Element root, String tag) {
        List<Pose> out = new ArrayList<>();
        for (Element e : Dom.descendants(root, tag)) {
            Dom.optionalChild(e, "Position")
                    .ifPresent(p -> out.add(pose(Dom.child(p, "WorldPosition"), Double.NaN)));
        }
        return out;
    }

    /** Where the footprint's centre is when the vehicle's reference point stands at {@code p}. */
    private static Pose centred(Pose p, Box box) {
        if (box == null) {
            throw new AssertionError("a position is given for an entity that is not declared");
        }
        double cos = Math.cos(p.h());
        double sin = Math.sin(p.h());
        return new Pose(p.time(), p.x() + cos * box.centreX() - sin * box.centreY(),
                p.y() + sin * box.centreX() + cos * box.centreY(), p.h());
    }

    private static Pose pose(Element w, double time) {
        return new Pose(time, Dom.number(w, "x"), Dom.number(w, "y"), Dom.number(w, "h", 0));
    }

    private static <T> void put(Map<String, T> map, String key, T value) {
        if (map.put(key, value) != null) {
            throw new AssertionError("\"" + key + "\" is given twice");
        }
    }
}
