package sitcov.judge;

import java.util.List;
import sitcov.oracle.RunResult;

/** A map run fault-free and once per fault with the same internal seed, each fault judged; and the ticks all runs cost. */
public record JudgedMap(RunResult faultFree, List<FaultVerdict> verdicts) {
    public JudgedMap {
        verdicts = List.copyOf(verdicts);
    }

    public long ticks() {
        return faultFree.ticks() + verdicts.stream().mapToLong(v -> v.faultyRun().ticks()).sum();
    }
}
