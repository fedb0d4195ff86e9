package sitcov.world;

/** Something the generator tried to place and could not, with why. */
public record Omission(String element, String reason) {
    @Override
    public String toString() {
        return element + ": " + reason;
    }
}
