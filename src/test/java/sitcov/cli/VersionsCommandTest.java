package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class VersionsCommandTest {
    @Test
    void versionsWritesAnOrdinaryResultsFolderWhoseVerdictGivesEachVariantAgainstTheReference(@TempDir Path dir)
            throws Exception {
        Path out = dir.resolve("v");
        CliRunner r = CliRunner.run("versions", "--reference", "builtin", "--variants", "builtin:4;builtin:16", "--maps", "3",
                "--threads", "1", "--out", out.toString());
        assertEquals(ExitCode.OK, r.exitCode(), r.err());
        List<String> rows = Files.readAllLines(out.resolve("runs.csv"));
        List<String> header = List.of(rows.get(0).split(","));
        int variant = header.indexOf("fault");
        int detection = header.indexOf("detection");
        long maps = rows.stream().skip(1).filter(l -> l.split(",", -1)[variant].equals("NONE")).count();
        assertTrue(maps >= 1 && maps <= 3, "at most the 3 maps drawn are judged: " + maps);
        assertEquals(1 + 3 * maps, rows.size(), "a header and, per map, the reference's row and one per variant");
        // fault 4 (a steering fault) leaves the road on almost every map: it must regress somewhere
        long regressedWith4 = rows.stream().skip(1).map(l -> l.split(",", -1))
                .filter(c -> c[variant].equals("4") && c[detection].equals("FOUND")).count();
        assertTrue(regressedWith4 > 0, String.join("\n", rows));
        String verdict = Files.readString(out.resolve("verdict.txt"));
        assertTrue(verdict.contains("variant 4 (waypoints-south-east): fails where the reference did not on "
                + regressedWith4 + " of " + maps + " maps"), verdict);
        assertTrue(verdict.contains("variant 16 (second-pull-out)"), verdict);
        assertTrue(Files.isRegularFile(out.resolve("report.html")), "the same report as run's");
    }

    @Test
    void aControllerThatFailsItsHandshakeStopsVersionsBeforeAnyFolderIsMade(@TempDir Path dir) {
        Path out = dir.resolve("never");
        CliRunner r = CliRunner.run("versions", "--reference", "exec:sh -c 'exit 3'", "--variants", "builtin",
                "--maps", "2", "--out", out.toString());
        assertEquals(ExitCode.USAGE, r.exitCode(), r.err());
        assertTrue(r.err().contains("failed the handshake"), r.err());
        assertTrue(!Files.exists(out), "nothing is written for a controller that cannot start");
    }

    @Test
    void aComparisonWithNoVariantIsRefusedBeforeAnythingRuns(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("never");
        for (String variants : List.of("none", ";", ";;", " ; ", "\t;")) {
            CliRunner r = CliRunner.run("versions", "--reference", "builtin", "--variants", variants, "--maps", "2", "--out",
                    out.toString());
            assertEquals(ExitCode.USAGE, r.exitCode(), "'" + variants + "': " + r.out() + r.err());
            assertTrue(r.err().contains("versions: --variants '" + variants.strip() + "' names no variant; name at least"
                    + " one, e.g. --variants 'builtin:16', separated by ';'."), r.err());
        }
        Path preset = dir.resolve("nothing.properties");
        Files.writeString(preset, "reference=builtin\nvariants=;\nmaps=2\n");
        CliRunner fromPreset = CliRunner.run("versions", preset.toString(), "--out", out.toString());
        assertEquals(ExitCode.USAGE, fromPreset.exitCode(), fromPreset.out() + fromPreset.err());
        assertTrue(fromPreset.err().contains("names no variant"), fromPreset.err());
        assertFalse(Files.exists(out), "nothing is written");
    }

    @Test
    void aPresetWhoseVariantsAreOnlySeparatorsIsToldToNameOneOrWriteNone(@TempDir Path dir) throws Exception {
        Path preset = dir.resolve("separators.properties");
        Files.writeString(preset, Files.readString(Path.of(ResultsFolders.TINY)).replace("faults=14,19", "variants=;"));
        CliRunner r = CliRunner.run("run", preset.toString(), "--out", dir.resolve("never").toString());
        assertEquals(ExitCode.USAGE, r.exitCode(), r.err());
        assertTrue(r.err().contains("';' names no variant; name at least one, e.g. builtin:16, separated by ';', or write"
                + " none for none."), r.err());
        assertFalse(Files.exists(dir.resolve("never")), "nothing is written");
    }

    @Test
    void aPresetThatDoesNotExistIsNamedWithTheShippedOne() {
        CliRunner r = CliRunner.run("versions", "nosuch");
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("versions: no preset 'nosuch'") && r.err().contains("byo-controller"), r.err());
    }

    @Test
    void aVariantThatNamesNoControllerIsRefusedWithTheFix() {
        CliRunner r = CliRunner.run("versions", "--reference", "builtin", "--variants", "builtin:99", "--maps", "2");
        assertEquals(ExitCode.USAGE, r.exitCode());
        assertTrue(r.err().contains("'99' is not a fault") && r.err().contains("ids 0-19"), r.err());
    }
}
