package sitcov.faults;

/**
 * What one fault did in one run: whether its faulty code path ran ({@code reached}), how often it
 * changed a value the car then used ({@code effectiveCount}), and the first tick it did so
 * ({@code -1} if never).
 */
public record Activation(Fault fault, boolean active, boolean reached, long effectiveCount, long firstEffectiveTick) {
    public boolean effective() {
        return effectiveCount > 0;
    }
}
