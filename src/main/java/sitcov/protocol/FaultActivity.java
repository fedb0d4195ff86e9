package sitcov.protocol;

import sitcov.faults.Activation;
import sitcov.faults.Fault;
import sitcov.faults.FaultSwitchboard;

/**
 * The controller side's fault activations tick by tick: what its switchboard recorded since the
 * last command (faults newly reached, and how many more times each was effective), so that sitcov,
 * replaying them into the run's own switchboard at the same tick, records what an in-process run
 * records. Written only when something happened.
 */
final class FaultActivity {
    private static final Fault[] FAULTS = Fault.values();

    private final FaultSwitchboard faults;
    private final boolean[] reached = new boolean[FAULTS.length];
    private final long[] effective = new long[FAULTS.length];

    FaultActivity(FaultSwitchboard faults) {
        this.faults = faults;
    }

    /** Writes a "faults" member with what changed since the last call, or nothing when nothing did. */
    void write(JsonWriter w) {
        boolean any = false;
        for (Fault f : FAULTS) {
            Activation a = faults.activation(f);
            if (a.reached() != reached[f.ordinal()] || a.effectiveCount() != effective[f.ordinal()]) {
                any = true;
            }
        }
        if (!any) {
            return;
        }
        w.name("faults").beginObject().name("reached").beginArray();
        for (Fault f : FAULTS) {
            Activation a = faults.activation(f);
            if (a.reached() && !reached[f.ordinal()]) {
                w.value(f.id());
                reached[f.ordinal()] = true;
            }
        }
        w.endArray().name("effective").beginArray();
        for (Fault f : FAULTS) {
            Activation a = faults.activation(f);
            long more = a.effectiveCount() - effective[f.ordinal()];
            if (more > 0) {
                w.beginArray().value(f.id()).value(more).endArray();
                effective[f.ordinal()] = a.effectiveCount();
            }
        }
        w.endArray().endObject();
    }
}
