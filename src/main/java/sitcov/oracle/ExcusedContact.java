package sitcov.oracle;

/**
 * A contact with a moving car that the blame rules excused: when it began, the rule that excused it,
 * where the car's front centre was and the other car's id. Not an accident; kept so that a player
 * that reports every contact can be matched against the run.
 */
public record ExcusedContact(long tick, Blame blame, double x, double y, int otherParty) {
}
