package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class FaultsCommandTest {
    @Test
    void listingShowsAllTwentyFaultsAndMarksThePapersSeven() {
        CliRunner r = CliRunner.run("faults");
        assertEquals(0, r.exitCode(), r.err());
        long rows = r.out().lines().filter(l -> l.matches("\\s*\\d+ [* ] \\S+.*")).count();
        long starred = r.out().lines().filter(l -> l.matches("\\s*\\d+ \\* \\S+.*")).count();
        assertEquals(20, rows, r.out());
        assertEquals(7, starred, r.out());
        assertTrue(r.out().contains("18 * obstacle-search-along-heading"), r.out());
    }

    @Test
    void calibrationPrintsOneRowPerFaultWithItsShares() {
        CliRunner r = CliRunner.run("faults", "--calibrate", "--maps", "2", "--faults", "2,19", "--threads", "2");
        assertEquals(0, r.exitCode(), r.err());
        assertTrue(r.out().contains("faults 2,19"), r.out());
        // waypoints 1 m north-east put the car over a kerb or the centre line on every map
        assertTrue(r.out().lines().anyMatch(l -> l.matches("\\s+2  waypoints-north-east\\s+100\\.0%\\s+100\\.0%\\s+100\\.0%.*")),
                r.out());
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith(" 19  oncoming-at-half-speed")), r.out());
        assertTrue(r.out().contains("Reproduce: experiments/sitcov faults --calibrate --maps 2 --seed 1 --faults 2,19"), r.out());
    }

    @Test
    void calibrationOutputDoesNotDependOnTheThreadCount() {
        CliRunner one = CliRunner.run("faults", "--calibrate", "--maps", "3", "--faults", "8,14", "--threads", "1");
        CliRunner two = CliRunner.run("faults", "--calibrate", "--maps", "3", "--faults", "8,14", "--threads", "2");
        assertEquals(one.out(), two.out());
    }

    @Test
    void anUnknownFaultIsRefusedWithTheValidListAndExitCode2() {
        CliRunner r = CliRunner.run("faults", "--calibrate", "--maps", "2", "--faults", "4,20");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("'20' is not a fault") && r.err().contains("ids 0-19"), r.err());
        assertEquals("", r.out());
    }

    @Test
    void calibratingWithoutAMapCountSaysWhatToAdd() {
        CliRunner r = CliRunner.run("faults", "--calibrate");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("--maps N"), r.err());
    }

    @Test
    void calibrationOptionsWithoutCalibrateAreRefused() {
        CliRunner r = CliRunner.run("faults", "--maps", "5");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("goes with --calibrate"), r.err());
    }

    @Test
    void calibrationForkedAndRunWholeAgreesByteForByte() {
        CliRunner forked = CliRunner.run("faults", "--calibrate", "--maps", "4", "--faults", "ALL", "--threads", "1");
        CliRunner whole = CliRunner.run("faults", "--calibrate", "--maps", "4", "--faults", "ALL", "--threads", "1",
                "--fork", "off");
        assertEquals(0, whole.exitCode(), whole.err());
        assertTrue(forked.out().contains("FOUND"), forked.out());
        assertEquals(whole.out(), forked.out());
    }

    @Test
    void aForkSettingOtherThanOnOrOffIsRefusedWithExitCode2() {
        CliRunner r = CliRunner.run("faults", "--calibrate", "--maps", "2", "--fork", "maybe");
        assertEquals(2, r.exitCode());
        assertTrue(r.err().contains("--fork takes on or off, not 'maybe'"), r.err());
        assertEquals("", r.out());
    }

    @Test
    void theListingShowsTheSeamFaultsByTheirIds() {
        CliRunner r = CliRunner.run("faults");
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith("seam:late-frame ")), r.out());
        assertEquals(14, r.out().lines().filter(l -> l.startsWith("seam:")).count(), r.out());
    }

    @Test
    void seamFaultsAreCalibratedOnTheBuiltinCarForkedAndWholeAlike() {
        String[] args = {"faults", "--calibrate", "--maps", "2", "--faults", "seam:late-command,seam:lane-offset-bias",
            "--threads", "2"};
        CliRunner forked = CliRunner.run(args);
        assertEquals(0, forked.exitCode(), forked.err());
        // two ticks late, the builtin car's lane keeping weaves off its lane on both maps; it reads no channel
        assertTrue(forked.out().lines().anyMatch(l -> l.matches("seam:late-command\\s+100\\.0%\\s+100\\.0%\\s+100\\.0%.*")),
                forked.out());
        assertTrue(forked.out().lines().anyMatch(l -> l.matches("seam:lane-offset-bias\\s+0\\.0%\\s+0\\.0%\\s+0\\.0%.*")),
                forked.out());
        String[] whole = java.util.Arrays.copyOf(args, args.length + 2);
        whole[args.length] = "--fork";
        whole[args.length + 1] = "off";
        assertEquals(forked.out(), CliRunner.run(whole).out());
    }

    @Test
    void anUnknownSeamFaultOrAControllerForSeededFaultsIsRefusedWithExitCode2() {
        CliRunner unknown = CliRunner.run("faults", "--calibrate", "--maps", "2", "--faults", "seam:fog");
        assertEquals(2, unknown.exitCode());
        assertTrue(unknown.err().contains("seam:fog") || unknown.err().contains("'fog'"), unknown.err());
        assertTrue(unknown.err().contains("radar-dropout"), unknown.err());
        CliRunner seeded = CliRunner.run("faults", "--calibrate", "--maps", "2", "--faults", "2", "--controller",
                "exec:python3 experiments/controllers/route_driver.py");
        assertEquals(2, seeded.exitCode());
        assertTrue(seeded.err().contains("--faults seam:ALL"), seeded.err());
    }
}
