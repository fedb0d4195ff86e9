package sitcov.experiment;

/**
 * Shard {@code k} of {@code n}: the replications whose index is {@code k-1} modulo {@code n}. Dealt
 * round-robin so every shard gets a like share of a sweep's small and large budgets.
 */
public record Shard(int k, int n) {
    public static final Shard WHOLE = new Shard(1, 1);

    public Shard {
        if (n < 1 || k < 1 || k > n) {
            throw new IllegalArgumentException("a shard is K/N with 1 <= K <= N, got " + k + "/" + n);
        }
    }

    public static Shard parse(String text) {
        String[] parts = text.strip().split("/");
        try {
            if (parts.length == 2) {
                return new Shard(Integer.parseInt(parts[0].strip()), Integer.parseInt(parts[1].strip()));
            }
        } catch (NumberFormatException e) {
            // falls through to the message below
        }
        throw new IllegalArgumentException("a shard is K/N such as 2/3, got '" + text + "'");
    }

    public boolean includes(int replication) {
        return replication % n == k - 1;
    }

    public boolean isWhole() {
        return n == 1;
    }

    @Override
    public String toString() {
        return k + "/" + n;
    }
}
