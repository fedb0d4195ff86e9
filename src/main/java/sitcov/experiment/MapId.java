package sitcov.experiment;

/**
 * What a driver ran: a map generated from an external seed, or a situation a driver built or
 * edited, kept as a situation file in the results folder. Its text form names it in runs.csv.
 */
public sealed interface MapId {
    /** The text in runs.csv: {@code seed:N} or {@code situation:NAME}. */
    String text();

    /** A map the generator makes from {@code externalSeed}. */
    record Seeded(long externalSeed) implements MapId {
        @Override
        public String text() {
            return "seed:" + externalSeed;
        }
    }

    /**
     * A situation a driver built; {@code name} is unique within an experiment and names its file
     * {@code situations/NAME.situation} in the results folder (a name run twice in a replication is
     * refused by {@link SharedMaps}, a file holding another situation by the journal's writer).
     */
    record Situation(String name) implements MapId {
        public Situation {
            if (!name.matches("[A-Za-z0-9][A-Za-z0-9._-]{0,99}")) {
                throw new IllegalArgumentException("a situation name is letters, digits, '.', '_' and '-', got '" + name + "'");
            }
        }

        @Override
        public String text() {
            return "situation:" + name;
        }
    }

    /** Reads the text form back. */
    static MapId parse(String text) {
        if (text.startsWith("seed:")) {
            return new Seeded(Long.parseLong(text.substring(5)));
        }
        if (text.startsWith("situation:")) {
            return new Situation(text.substring(10));
        }
        throw new IllegalArgumentException("a map is 'seed:N' or 'situation:NAME', got '" + text + "'");
    }
}
