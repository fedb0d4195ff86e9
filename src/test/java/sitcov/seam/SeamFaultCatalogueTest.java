package sitcov.seam;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

class SeamFaultCatalogueTest {
    private static final Path CATALOGUE = Path.of("faults", "README.md");
    private static final Pattern ROW = Pattern.compile("^\\| `(seam:[a-z0-9-]+)` \\| ([^|]+) \\|$");

    @Test
    void theCatalogueTableListsEverySeamFaultOfTheCodeInOrder() throws IOException {
        List<String> inCatalogue = Files.readAllLines(CATALOGUE, StandardCharsets.UTF_8).stream()
                .map(ROW::matcher).filter(Matcher::matches).map(m -> m.group(1)).toList();
        assertEquals(Arrays.stream(SeamFault.values()).map(SeamFault::spec).toList(), inCatalogue);
    }

    @Test
    void atLeastTwelveFaultsActOnTheObservationAndOnTheCommand() {
        long onCommand = Arrays.stream(SeamFault.values()).filter(SeamFault::actsOnCommand).count();
        assertTrue(SeamFault.values().length >= 12);
        assertEquals(4, onCommand, "steering bias, steering stuck, half braking, late command");
    }

    @Test
    void allNamesTheCatalogueAndAnUnknownNameIsRefusedWithTheValidOnes() {
        assertEquals(List.of(SeamFault.values()), SeamFault.parse("seam:ALL"));
        assertEquals(List.of(SeamFault.LATE_FRAME), SeamFault.parse("seam:late-frame"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SeamFault.parse("seam:fog"));
        assertTrue(e.getMessage().contains("radar-dropout") && e.getMessage().contains("seam:ALL"), e.getMessage());
    }
}
