package sitcov.export;

import java.util.List;
import java.util.Locale;
import sitcov.geom.Bearing;
import sitcov.vehicles.AutonomousCar;
import sitcov.vehicles.Dynamics;
import sitcov.vehicles.MovingCar;
import sitcov.vehicles.TargetArrival;
import sitcov.world.Dimensions;
import sitcov.world.Target;

/**
 * The pieces every exported OpenSCENARIO document shares: its header, road network, vehicles,
 * positions, triggers and the stop at the Target. Each vehicle's position is its rear axle, as
 * the standard places vehicles; its bounding box's centre lies ahead of it.
 */
final class ScenarioParts {
    /** Exports carry no clock time, so that the same map gives the same bytes; the header needs a date. */
    static final String FIXED_DATE = "2026-01-01T00:00:00";
    private static final double TICK = Dimensions.TICK_SECONDS;
    private static final double FRONT_AXLE_BEHIND_FRONT = 0.8;

    private ScenarioParts() {
    }

    /**
     * A kind of vehicle: its size, its rear axle (which it turns about) behind its front, and the
     * model a player draws. CARLA's ScenarioRunner takes a vehicle's name for the CARLA blueprint
     * to spawn, so the names are blueprints of about the right size; other players ignore them.
     */
    record Kind(String model, double length, double width, double rearAxleBehindFront) {
        static final Kind CAR_UNDER_TEST = new Kind("vehicle.micro.microlino", Dimensions.AUTONOMOUS_CAR_LENGTH,
                Dimensions.AUTONOMOUS_CAR_WIDTH, AutonomousCar.REAR_AXLE);
        static final Kind PARKED = new Kind("vehicle.lincoln.mkz_2020", Dimensions.CAR_LENGTH, Dimensions.CAR_WIDTH,
                MovingCar.REAR_AXLE);
        static final Kind MOVING = PARKED;

        /** The kind of a recorded track's vehicle. */
        static Kind of(RunRecording.Track track) {
            return track.entity().equals(RunRecording.EGO) ? CAR_UNDER_TEST : MOVING;
        }

        /** The footprint's centre ahead of the rear axle, the reference point OpenSCENARIO places a vehicle by. */
        double centreAheadOfRearAxle() {
            return rearAxleBehindFront - length / 2;
        }

        /** The rear axle's sitcov x when the front centre, where sitcov anchors vehicles, is at {@code frontX}. */
        double rearAxleX(double frontX, double bearing) {
            return frontX - Bearing.dx(bearing) * rearAxleBehindFront;
        }

        /** The rear axle's sitcov y when the front centre is at {@code frontY}. */
        double rearAxleY(double frontY, double bearing) {
            return frontY - Bearing.dy(bearing) * rearAxleBehindFront;
        }
    }

    static void header(Xml xml, ScenarioVersion version, String description) {
        xml.empty("FileHeader", "revMajor", "1", "revMinor", Integer.toString(version.minor()), "date", FIXED_DATE,
                "description", description, "author", "sitcov");
    }

    /** A parameter or variable: its name, its type (as OpenSCENARIO names types) and its value at the start. */
    record Declaration(String name, String type, String value) {
    }

    /**
     * The variables a scenario changes as it runs (parameters before 1.2), catalogs and the road network, in the
     * order the schema wants them.
     */
    static void context(Xml xml, ScenarioVersion version, List<Declaration> variables, String roadFile) {
        if (!variables.isEmpty()) {
            String what = version.hasVariables() ? "Variable" : "Parameter";
            xml.open(what + "Declarations");
            for (Declaration d : variables) {
                xml.empty(what + "Declaration", "name", d.name(), what.toLowerCase(Locale.ROOT) + "Type", d.type(),
                        "value", d.value());
            }
            xml.close();
        }
        xml.empty("CatalogLocations");
        xml.open("RoadNetwork");
        xml.empty("LogicFile", "filepath", roadFile);
        xml.close();
    }

    /**
     * A vehicle and its properties: ScenarioRunner takes the ego vehicle by its {@code type}, esmini interpolates
     * a trajectory's headings by its {@code plineInterpolation}, and a recording tells its run on the ego.
     */
    static void vehicle(Xml xml, String entity, Kind kind, List<Declaration> properties) {
        xml.open("ScenarioObject", "name", entity);
        xml.open("Vehicle", "name", kind.model(), "vehicleCategory", "car");
        xml.open("BoundingBox");
        xml.empty("Center", "x", Xml.metres(kind.centreAheadOfRearAxle()), "y", Xml.metres(0), "z", Xml.metres(0.75));
        xml.empty("Dimensions", "width", Xml.metres(kind.width()), "length", Xml.metres(kind.length()),
                "height", Xml.metres(1.5));
        xml.close();
        // sitcov's limits in the formats' units: metres a tick become metres a second
        xml.empty("Performance", "maxSpeed", Xml.metres(Dynamics.MAX_SPEED / TICK),
                "maxAcceleration", Xml.metres(Dynamics.ACCELERATION / TICK / TICK),
                "maxDeceleration", Xml.metres(Dynamics.BRAKING / TICK / TICK));
        xml.open("Axles");
        // positions are the rear axle's, so it sits at 0; the front axle 0.8 m behind the front
        axle(xml, "FrontAxle", kind.rearAxleBehindFront() - FRONT_AXLE_BEHIND_FRONT);
        axle(xml, "RearAxle", 0);
        xml.close();
        if (properties.isEmpty()) {
            xml.empty("Properties");
        } else {
            xml.open("Properties");
            for (Declaration p : properties) {
                xml.empty("Property", "name", p.name(), "value", p.value());
            }
            xml.close();
        }
        xml.close().close();
    }

    private static void axle(Xml xml, String which, double positionX) {
        xml.empty(which, "maxSteering", Xml.fine(Math.toRadians(Dynamics.MAX_TURN)), "wheelDiameter", Xml.metres(0.6),
                "trackWidth", Xml.metres(1.6), "positionX", Xml.metres(positionX), "positionZ", Xml.metres(0.3));
    }

    /**
     * A vehicle's world position from its sitcov pose (the front centre): its rear axle, the
     * reference point OpenSCENARIO places vehicles by and players turn them about.
     */
    static void vehiclePose(Xml xml, double frontX, double frontY, double bearing, Kind kind) {
        worldPose(xml, kind.rearAxleX(frontX, bearing), kind.rearAxleY(frontY, bearing), bearing);
    }

    /** A parked car's world position from the centre of its footprint. */
    static void parkedPose(Xml xml, double centreX, double centreY, double bearing) {
        double ahead = Kind.PARKED.length() / 2;
        vehiclePose(xml, centreX + Bearing.dx(bearing) * ahead, centreY + Bearing.dy(bearing) * ahead, bearing, Kind.PARKED);
    }

    static void worldPose(Xml xml, double x, double y, double bearing) {
        xml.open("Position");
        xml.empty("WorldPosition", "x", Xml.metres(AsamFrame.x(x)), "y", Xml.metres(AsamFrame.y(y)),
                "h", Xml.angle(AsamFrame.heading(bearing)));
        xml.close();
    }

    static void targetPosition(Xml xml, Target target) {
        xml.open("Position");
        xml.empty("WorldPosition", "x", Xml.metres(AsamFrame.x(target.position().x())),
                "y", Xml.metres(AsamFrame.y(target.position().y())), "z", Xml.metres(0));
        xml.close();
    }

    static void speed(Xml xml, double metresPerSecond, String shape, String dimension, double value) {
        xml.open("PrivateAction").open("LongitudinalAction").open("SpeedAction");
        xml.empty("SpeedActionDynamics", "dynamicsShape", shape, "value", Xml.metres(value), "dynamicsDimension", dimension);
        xml.open("SpeedActionTarget");
        xml.empty("AbsoluteTargetSpeed", "value", Xml.metres(metresPerSecond));
        xml.close().close().close().close();
    }

    /** A trigger that fires once the simulation time passes {@code seconds}. */
    static void timeTrigger(Xml xml, String element, String name, double seconds) {
        xml.open(element).open("ConditionGroup");
        timeCondition(xml, name, seconds);
        xml.close().close();
    }

    static void timeCondition(Xml xml, String name, double seconds) {
        // edge "none": a time already passed when the act starts (0 s) fires at once; a rising edge never would
        xml.open("Condition", "name", name, "delay", "0", "conditionEdge", "none");
        xml.open("ByValueCondition");
        xml.empty("SimulationTimeCondition", "value", Xml.seconds(seconds), "rule", "greaterThan");
        xml.close().close();
    }

    /**
     * The storyboard's stop: the car under test on the Target (its front within sitcov's capture
     * distance; a player measures from its reference point, the rear axle, so the tolerance adds
     * the distance between them), or else the time limit.
     */
    static void stopAtTargetOrTimeout(Xml xml, Target target, double timeoutSeconds, ScenarioVersion version) {
        xml.open("StopTrigger");
        xml.open("ConditionGroup");
        xml.open("Condition", "name", "the car under test reaches the Target", "delay", "0", "conditionEdge", "rising");
        xml.open("ByEntityCondition");
        xml.open("TriggeringEntities", "triggeringEntitiesRule", "any");
        xml.empty("EntityRef", "entityRef", RunRecording.EGO);
        xml.close();
        xml.open("EntityCondition");
        String tolerance = Xml.metres(TargetArrival.CAPTURE_DISTANCE + Kind.CAR_UNDER_TEST.rearAxleBehindFront());
        if (version.reachesByDistance()) {
            xml.open("DistanceCondition", "freespace", "false", "rule", "lessThan", "value", tolerance,
                    "coordinateSystem", "entity", "relativeDistanceType", "euclidianDistance");
        } else {
            xml.open("ReachPositionCondition", "tolerance", tolerance);
        }
        targetPosition(xml, target);
        xml.close().close().close().close();
        xml.close();
        xml.open("ConditionGroup");
        timeCondition(xml, "time limit", timeoutSeconds);
        xml.close();
        xml.close();
    }
}
