package sitcov.judge;

import java.util.List;
import sitcov.oracle.RunResult;
import sitcov.vehicles.CommandLog;

/**
 * A map run fault-free and once per fault with the same internal seed, each fault judged; and the
 * commands each run carried out: the reference's first, then each variant's in the verdicts' order
 * (none, once they are let go of).
 */
public record JudgedMap(RunResult faultFree, List<FaultVerdict> verdicts, List<CommandLog> commands) {
    public JudgedMap {
        verdicts = List.copyOf(verdicts);
        commands = List.copyOf(commands);
        if (!commands.isEmpty() && commands.size() != 1 + verdicts.size()) {
            throw new IllegalArgumentException("a judged map keeps the commands of its reference run and of each of its "
                    + verdicts.size() + " variants' runs, got " + commands.size());
        }
    }

    /** The same map judged, its runs' commands let go of. */
    public JudgedMap withoutCommands() {
        return new JudgedMap(faultFree, verdicts, List.of());
    }

    public long ticks() {
        return faultFree.ticks() + verdicts.stream().mapToLong(v -> v.faultyRun().ticks()).sum();
    }
}
