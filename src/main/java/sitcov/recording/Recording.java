package sitcov.recording;

import sitcov.oracle.Outcome;
import sitcov.vehicles.CommandLog;

/**
 * One run's recording: which run of the folder it is, its seeds, how it ended and after how many
 * ticks, and the commands the world carried out. Replayed on the same map and seeds, the commands
 * give the same run, which must end in {@code outcome} after {@code ticks}.
 */
public record Recording(RunKey key, long externalSeed, long internalSeed, Outcome outcome, long ticks,
                        CommandLog commands) {
    /**
     * A run of a results folder: the map of {@code driver}'s {@code mapIndex} in {@code replication},
     * run by the reference ({@code variant} {@link #REFERENCE}) or by the variant with that id.
     */
    public record RunKey(int replication, String driver, int mapIndex, int variant) {
        /** The reference's: no variant's id, which is never negative (fault 0 is a variant's id 0). */
        public static final int REFERENCE = -1;

        /** The file name of its recording: {@code r1-random-m12-v3.jsonl.gz}, {@code -ref} for the reference. */
        public String fileName() {
            return "r" + replication + "-" + driver + "-m" + mapIndex + "-"
                    + (variant == REFERENCE ? "ref" : "v" + variant) + RecordingFile.SUFFIX;
        }
    }

    /** Where a replay of it stops: after its last tick when the experiment stopped it at its verdict, else never. */
    public long stopAfter() {
        return outcome == Outcome.STOPPED_AT_VERDICT ? ticks : Long.MAX_VALUE;
    }
}
