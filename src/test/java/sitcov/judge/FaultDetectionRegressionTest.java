package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import sitcov.builtin.BuiltinRuns;
import sitcov.faults.Fault;
import sitcov.oracle.RunResult;
import sitcov.world.SituationFile;
import sitcov.world.WorldMap;

/**
 * Regression of fault detection: for every seeded fault, a committed situation and internal seed
 * (listed in {@code regression/faults.txt}) on which the differential oracle finds the fault and the
 * fault-free run has no accident.
 */
class FaultDetectionRegressionTest {
    static final Path FOLDER = Path.of("src", "test", "resources", "regression");

    record Case(Fault fault, String file, long internalSeed) {
        String replay() {
            return "replay: sitcov simulate --load " + FOLDER.resolve(file) + " --internal-seed " + internalSeed
                    + " --faults " + fault.id();
        }
    }

    static List<Case> cases() throws IOException {
        List<Case> cases = new ArrayList<>();
        for (String line : Files.readAllLines(FOLDER.resolve("faults.txt"))) {
            String l = line.strip();
            if (l.isEmpty() || l.startsWith("#")) {
                continue;
            }
            String[] f = l.split("\\s+");
            cases.add(new Case(Fault.ofId(Integer.parseInt(f[0])), f[1], Long.parseLong(f[2])));
        }
        return cases;
    }

    @Test
    void everyFaultHasExactlyOneRegressionSituation() throws IOException {
        List<Integer> ids = cases().stream().map(c -> c.fault().id()).toList();
        assertEquals(Stream.of(Fault.values()).map(Fault::id).toList(), ids, "faults.txt must list ids 0..19 in order");
    }

    @TestFactory
    Stream<DynamicTest> eachFaultIsFoundOnItsSituation() throws IOException {
        return cases().stream().map(c -> DynamicTest.dynamicTest(
                "fault " + c.fault().id() + " (" + c.fault().label() + ") is FOUND on " + c.file(), () -> {
                    WorldMap map = SituationFile.read(FOLDER.resolve(c.file()));
                    JudgedMap judged = BuiltinRuns.judge(map, c.internalSeed(), List.of(c.fault()));
                    RunResult faultFree = judged.faultFree();
                    FaultVerdict verdict = judged.verdicts().get(0);
                    assertFalse(faultFree.hasAccident(), "the fault-free run has accidents " + faultFree.accidents()
                            + "; " + c.replay());
                    assertEquals(Detection.FOUND, verdict.detection(), verdict + "; " + c.replay());
                }));
    }
}
