package sitcov.export;

import java.util.List;

/**
 * A recorded run's declared accidents and contacts ({@link Declared}) written as the events of one maneuver: each
 * starts when a player sees it and sets its variable (a parameter before OpenSCENARIO 1.2) from false to true, so
 * the player's log says when it saw each one and its variables say which it saw. A contact's event waits for the
 * two vehicles to come to touch, from half a tick before the last sample they were apart; an accident with no
 * other party starts at its time.
 */
final class DeclaredEvents {
    private DeclaredEvents() {
    }

    /** The variables (or parameters), one per declared event, each false until its event starts. */
    static List<ScenarioParts.Declaration> variables(List<Declared> declared) {
        return declared.stream().map(d -> new ScenarioParts.Declaration(d.id(), "boolean", "false")).toList();
    }

    static void maneuverGroup(Xml xml, List<Declared> declared, ScenarioVersion version) {
        if (declared.isEmpty()) {
            return;
        }
        xml.open("ManeuverGroup", "maximumExecutionCount", "1", "name", "what sitcov saw");
        OpenScenario.actors(xml, RunRecording.EGO);
        xml.open("Maneuver", "name", "the run's accidents and contacts");
        for (Declared d : declared) {
            xml.open("Event", "name", d.describe(), "priority", "parallel");
            xml.open("Action", "name", d.id() + " seen");
            xml.open("GlobalAction");
            if (version.hasVariables()) {
                xml.open("VariableAction", "variableRef", d.id());
            } else {
                xml.open("ParameterAction", "parameterRef", d.id());
            }
            xml.empty("SetAction", "value", "true");
            xml.close().close();
            xml.close();
            xml.open("StartTrigger").open("ConditionGroup");
            if (d.isContact()) {
                ScenarioParts.timeCondition(xml, d.id() + ": not before", RecordedTrack.triggerTime((int) d.tick()));
                touching(xml, d);
            } else {
                ScenarioParts.timeCondition(xml, d.id() + ": at its time", RecordedTrack.triggerTime((int) d.tick() + 1));
            }
            xml.close().close();
            xml.close();
        }
        xml.close();
        xml.close();
    }

    /** The two vehicles come to touch (a rising edge: the moment they do, not a while they are). */
    private static void touching(Xml xml, Declared d) {
        String other = d.other().orElseThrow();
        xml.open("Condition", "name", d.id() + ": " + d.entity() + " touches " + other, "delay", "0",
                "conditionEdge", "rising");
        xml.open("ByEntityCondition");
        xml.open("TriggeringEntities", "triggeringEntitiesRule", "any");
        xml.empty("EntityRef", "entityRef", d.entity());
        xml.close();
        xml.open("EntityCondition").open("CollisionCondition");
        xml.empty("EntityRef", "entityRef", other);
        xml.close().close();
        xml.close();
        xml.close();
    }
}
