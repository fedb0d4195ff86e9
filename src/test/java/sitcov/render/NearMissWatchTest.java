package sitcov.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import org.junit.jupiter.api.Test;
import sitcov.builtin.BuiltinRuns;
import sitcov.judge.Simulator;
import sitcov.oracle.Margins;
import sitcov.oracle.RunResult;
import sitcov.world.MapGenerator;
import sitcov.world.WorldMap;

class NearMissWatchTest {
    @Test
    void aWatchOfARunSeesWhatTheRunsOwnWatcherKept() {
        WorldMap map = MapGenerator.generate(1);
        NearMissWatch watch = new NearMissWatch();
        assertFalse(watch.started());
        assertThrows(IllegalStateException.class, watch::nearMisses);
        RunResult result = BuiltinRuns.run(map, 1, Set.of(), watch).result();
        assertTrue(watch.started());
        assertTrue(result.margins().known());
        assertEquals(result.margins(), Margins.of(watch.nearMisses()));
    }
}
