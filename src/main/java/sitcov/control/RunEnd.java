package sitcov.control;

/** How a run ended, as a controller is told: the outcome's name and the ticks run. */
public record RunEnd(String outcome, long ticks) {
}
