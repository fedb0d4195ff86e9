package sitcov.cli;

import java.io.PrintStream;
import java.util.List;
import java.util.Locale;
import sitcov.faults.Activation;
import sitcov.oracle.AccidentType;
import sitcov.oracle.Margins;
import sitcov.oracle.NearMiss;
import sitcov.oracle.NearMisses;
import sitcov.oracle.RunResult;
import sitcov.render.NearMissText;
import sitcov.render.NearMissWatch;

/** What {@code simulate} prints of one run below its line: clamped commands, the faults' activation, the near misses. */
final class RunDetails {
    private RunDetails() {
    }

    /** What the run's line leaves out: clamped commands, each planted fault's activation, the near misses. */
    static void print(PrintStream out, RunResult result, String firstClamp, List<Activation> activations,
                                     NearMissWatch nearMisses) {
        if (result.clampedTicks() > 0) {
            out.println("  clamped: the world clamped the command of " + result.clampedTicks() + " tick"
                    + (result.clampedTicks() == 1 ? "" : "s") + " to the car's limits, the first at " + firstClamp);
        }
        for (Activation a : activations) {
            if (a.active()) {
                out.println("  fault " + a.fault().id() + " (" + a.fault().label() + "): "
                        + (a.effective() ? "effective " + a.effectiveCount() + " times, first at tick " + a.firstEffectiveTick()
                        : a.reached() ? "reached, never effective" : "not reached"));
            }
        }
        if (nearMisses.started()) {
            printNearMisses(nearMisses.nearMisses(), out);
        }
    }

    /**
     * Each measure's least value and the tick it was first reached, and ρ per accident type, with
     * their units, as results keep them (4 decimals); beside the accidents, never counted as failures.
     */
    private static void printNearMisses(NearMisses watched, PrintStream out) {
        out.println("Near misses (the closest the run came; reported beside accidents, never counted as one):");
        for (NearMiss m : NearMiss.values()) {
            double v = watched.least(m);
            out.println(String.format(Locale.ROOT, "  %-27s %s", NearMissText.name(m),
                    NearMissText.value(m, v, Margins.DECIMALS) + (Double.isFinite(v) ? " at tick " + watched.tickOf(m) : "")));
        }
        out.println("Robustness ρ per accident type (below 0: that accident happened; the least over the run):");
        for (AccidentType t : AccidentType.values()) {
            out.println(String.format(Locale.ROOT, "  %-27s %s", t.name(),
                    NearMissText.rho(t, Margins.kept(watched.robustness(t)), Margins.DECIMALS)
                            + (t == AccidentType.TIMEOUT ? timeoutNote(watched.robustness(t)) : "")));
        }
    }

    private static String timeoutNote(double rho) {
        return Double.isNaN(rho) ? " (the run ended otherwise)" : rho == 0 ? " (timed out)" : " to spare before the timeout";
    }
}
