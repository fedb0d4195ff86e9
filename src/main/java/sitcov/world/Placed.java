package sitcov.world;

import java.util.List;

/** What a placement step put down, and how many it was asked for. */
record Placed<T>(List<T> items, int requested) {
}
