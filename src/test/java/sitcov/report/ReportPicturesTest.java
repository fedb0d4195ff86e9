package sitcov.report;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import sitcov.experiment.MapId;
import sitcov.experiment.MapRun;
import sitcov.faults.Fault;
import sitcov.judge.Detection;
import sitcov.judge.FaultOutcome;
import sitcov.judge.RunSummary;
import sitcov.judge.Variant;
import sitcov.oracle.Outcome;
import sitcov.render.ReplayGallery.Pictured;

/** Which failures and findings the report draws: all of a small folder's, and at most 24, in turns, of a large one's. */
class ReportPicturesTest {
    private static final Variant A = new Variant.Seeded(Fault.ofId(14));
    private static final Variant B = new Variant.Seeded(Fault.ofId(19));
    private static final List<Long> NO_ACCIDENT = List.of(0L, 0L, 0L, 0L, 0L);
    private static final List<Long> TIMED_OUT = List.of(0L, 0L, 0L, 0L, 1L);

    /** Map {@code m}: the reference failed by itself or not, each fault found or not. */
    private static MapRun map(int m, boolean own, boolean foundA, boolean foundB) {
        RunSummary passed = new RunSummary(Outcome.TARGET_REACHED, 100, NO_ACCIDENT);
        RunSummary reference = own ? new RunSummary(Outcome.TIMEOUT, 5000, TIMED_OUT) : passed;
        return new MapRun(0, "random", m, m, new MapId.Seeded(m), m, m, 0, List.of(), reference,
                List.of(outcome(A, foundA, passed), outcome(B, foundB, passed)));
    }

    private static FaultOutcome outcome(Variant v, boolean found, RunSummary run) {
        return new FaultOutcome(v, run, true, true, 1, found ? Detection.FOUND : Detection.EFFECT_NO_FAILURE,
                Optional.empty(), found);
    }

    private static List<Integer> rows(ReportPictures p, Optional<Variant> kind) {
        return p.of(kind).stream().map(Pictured::row).toList();
    }

    @Test
    void aLargeFolderHas24PicturesTakenInTurnsOwnFailuresFirstThenEachVariant() {
        // 40 maps: the reference fails on maps 0 and 1; A is found on every map, B on maps 5, 6 and 7
        List<MapRun> maps = new ArrayList<>();
        for (int m = 0; m < 40; m++) {
            maps.add(map(m, m < 2, true, m >= 5 && m < 8));
        }
        ReportPictures p = ReportPictures.of(List.of(A, B), maps);
        // a map's block is 3 rows: the reference's (3m+1), A's (3m+2), B's (3m+3). Turns: own, A, B, own, A, B,
        // then A, B (B's third and last), then A alone: 2 own, 3 of B, so 24 - 5 = 19 of A, its maps 0..18
        assertEquals(List.of(1, 4), rows(p, Optional.empty()));
        assertEquals(List.of(18, 21, 24), rows(p, Optional.of(B)));
        List<Integer> ofA = new ArrayList<>();
        for (int m = 0; m < 19; m++) {
            ofA.add(3 * m + 2);
        }
        assertEquals(ofA, rows(p, Optional.of(A)));
        assertEquals(24, p.drawn().size());
        assertEquals(2 + 40 + 3, p.candidates());
        assertEquals(List.of(true, false), p.of(Optional.of(A)).stream().limit(2).map(Pictured::first).toList(),
                "the first finding keeps the name fault-ID.png");
        assertEquals("replays/fault-14.png", p.of(Optional.of(A)).get(0).name());
        assertEquals("replays/row-5.png", p.of(Optional.of(A)).get(1).name());
    }

    @Test
    void aSmallFolderHasEveryFailureAndFindingPictured() {
        List<MapRun> maps = List.of(map(0, true, false, false), map(1, false, true, true), map(2, true, true, false));
        ReportPictures p = ReportPictures.of(List.of(A, B), maps);
        assertEquals(List.of(1, 7), rows(p, Optional.empty()));
        assertEquals(List.of(5, 8), rows(p, Optional.of(A)));
        assertEquals(List.of(6), rows(p, Optional.of(B)));
        assertEquals(5, p.drawn().size());
        assertEquals(5, p.candidates());
    }
}
