package sitcov.cli;

import java.util.List;

/** What a {@code versions} run compares: the reference and its variants on maps firstSeed, firstSeed+1, …. */
record VersionsPlan(String name, String reference, List<String> variants, int maps, long firstSeed) {
}
