package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import sitcov.world.Invariants;
import sitcov.world.MapGenerator;
import sitcov.world.SituationFile;
import sitcov.world.WorldMap;

/**
 * Situation files damaged at random (seeded): each either loads and keeps every rule of the world,
 * or is refused with exit 2 and a message naming it; never another exit code, a trace or a hang.
 */
class SituationFuzzTest {
    static final long SEED = 20261123;

    @TempDir
    Path dir;

    /** What became of the mutants: refused, accepted (and valid), or a finding (anything else). */
    record Tally(int refused, int accepted, List<String> findings) {
    }

    static Tally fuzz(Path dir, long seed, int mutants, boolean simulateSome) throws IOException {
        SplittableRandom random = new SplittableRandom(seed);
        List<String> originals = List.of(1L, 2L, 3L, 13L, 42L).stream()
                .map(s -> SituationFile.format(MapGenerator.generate(s))).toList();
        int refused = 0;
        int accepted = 0;
        List<String> findings = new java.util.ArrayList<>();
        for (int m = 0; m < mutants; m++) {
            Path file = dir.resolve("mutant-" + m + ".situation");
            String text = SituationMutator.mutate(originals.get(random.nextInt(originals.size())), random);
            Files.writeString(file, text, StandardCharsets.UTF_8);
            boolean simulate = simulateSome && m % 25 == 0;
            CliRunner r = simulate ? CliRunner.run("simulate", "--load", file.toString())
                    : CliRunner.run("map", "--load", file.toString());
            String where = "mutant " + m + " of seed " + seed + " (" + file + "): exit " + r.exitCode() + ", " + r.err();
            if (r.err().contains("Exception") || r.err().contains("\tat ")) {
                findings.add("a trace: " + where);
            } else if (r.exitCode() == 2 && r.err().contains(file.toString())) {
                refused++;
            } else if (r.exitCode() == 0) {
                try {
                    WorldMap map = SituationFile.read(file);
                    List<String> broken = Invariants.violations(map);
                    if (broken.isEmpty()) {
                        accepted++;
                    } else {
                        findings.add("accepted though it breaks " + broken + ": " + where);
                    }
                } catch (Exception e) {
                    findings.add("exit 0 but unreadable (" + e.getMessage() + "): " + where);
                }
            } else {
                findings.add(where);
            }
        }
        return new Tally(refused, accepted, findings);
    }

    @Test
    void everyDamagedSituationIsEitherValidOrRefusedNamingTheFile() {
        Tally t = assertTimeoutPreemptively(Duration.ofSeconds(90), () -> fuzz(dir, SEED, 300, true));
        if (!t.findings().isEmpty()) {
            fail(t.findings().size() + " findings, the first: " + t.findings().get(0));
        }
        assertEquals(300, t.refused() + t.accepted());
        assertTrue(t.refused() > 100 && t.accepted() > 10, "the mutants should both break and keep files: " + t);
    }

    /** The figures for a note: {@code java -cp target/classes:target/test-classes:JUNIT sitcov.cli.SituationFuzzTest 3000}. */
    public static void main(String[] args) throws IOException {
        int mutants = args.length > 0 ? Integer.parseInt(args[0]) : 3000;
        Path dir = ResultsFolders.scratch("sitcov-fuzz");
        Tally t = fuzz(dir, SEED, mutants, true);
        System.out.println(mutants + " mutants (seed " + SEED + "): " + t.refused() + " refused with exit 2 naming the file, "
                + t.accepted() + " accepted and valid, " + t.findings().size() + " anything else");
        t.findings().stream().limit(20).forEach(System.out::println);
    }
}
