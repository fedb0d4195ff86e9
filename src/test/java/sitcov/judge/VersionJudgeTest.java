package sitcov.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.List;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinCar;
import sitcov.builtin.BuiltinRuns;
import sitcov.control.ControllerFactory;
import sitcov.faults.Fault;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class VersionJudgeTest {
    private static final List<Fault> PLANTED = List.of(Fault.ofId(16), Fault.ofId(4), Fault.ofId(10));

    @Test
    void aVersionWithAPlantedFaultFailsExactlyWhereTheFaultIsFound() {
        // two paths to one answer: the experiment's faulty twin (MapRunner) and a version with the fault planted
        int regressions = 0;
        for (long seed = 1; seed <= 6; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            JudgedMap twins = BuiltinRuns.judge(map, seed, PLANTED, FaultyRuns.TO_END);
            List<VersionVerdict> versions = VersionJudge.judge(map, seed, BuiltinCar.FACTORY,
                    PLANTED.stream().<ControllerFactory>map(f -> BuiltinCar.withPlanted(EnumSet.of(f))).toList());
            for (int i = 0; i < PLANTED.size(); i++) {
                FaultVerdict twin = twins.verdicts().get(i);
                VersionVerdict version = versions.get(i);
                assertEquals(twin.detection() == Detection.FOUND, version.regressed(), "map " + seed + " fault " + PLANTED.get(i));
                assertEquals(twin.faultyRun().accidents(), version.run().accidents(), "map " + seed + " fault " + PLANTED.get(i));
                regressions += version.regressed() ? 1 : 0;
            }
        }
        assertTrue(regressions > 0, "the planted faults fail somewhere on these maps");
    }

    @Test
    void aPlantedFaultActsAsTheSameFaultSwitchedOnAndTheRunsOwnFaultsAreStillRecorded() {
        Fault planted = Fault.ofId(16);
        Fault judged = Fault.ofId(14);
        for (long seed = 1; seed <= 3; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            RunRecord both = BuiltinRuns.run(map, seed, EnumSet.of(planted, judged), RunObserver.NONE);
            RunRecord viaPlanted = Simulator.run(map, seed, EnumSet.of(judged), RunObserver.NONE,
                    BuiltinCar.withPlanted(EnumSet.of(planted)));
            assertEquals(both.result(), viaPlanted.result(), "map " + seed);
            assertEquals(both.activations().get(judged.ordinal()), viaPlanted.activations().get(judged.ordinal()), "map " + seed);
        }
    }

    @Test
    void theReferenceAgainstItselfNeverRegresses() {
        WorldMap map = MapGenerator.generate(3);
        VersionVerdict same = VersionJudge.judge(map, 3, BuiltinCar.FACTORY, List.of(BuiltinCar.FACTORY)).get(0);
        assertFalse(same.regressed());
        assertFalse(same.improved());
        assertEquals(same.reference(), same.run());
    }

    @Test
    void versionsWithPlantedFaultsForkedFromTheReferenceAreJudgedAsWhenRunWhole() {
        List<ControllerFactory> versions = List.of(BuiltinCar.withPlanted(EnumSet.of(Fault.ofId(19))),
                BuiltinCar.withPlanted(EnumSet.of(Fault.ofId(17), Fault.ofId(5))),
                BuiltinCar.withPlanted(EnumSet.of(Fault.ofId(12))), BuiltinCar.withPlanted(EnumSet.noneOf(Fault.class)));
        int regressions = 0;
        for (long seed = 1; seed <= 8; seed++) {
            WorldMap map = MapGenerator.generate(seed);
            List<VersionVerdict> forked = VersionJudge.judge(map, seed, BuiltinCar.FACTORY, versions);
            List<VersionVerdict> whole = VersionJudge.judge(map, seed, BuiltinCar.FACTORY.unforked(), versions);
            assertEquals(whole, forked, "map " + seed);
            regressions += (int) forked.stream().filter(VersionVerdict::regressed).count();
        }
        assertTrue(regressions > 0, "some versions fail where the reference does not");
    }
}
