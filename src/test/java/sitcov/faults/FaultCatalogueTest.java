package sitcov.faults;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * The human-readable catalogue {@code faults/README.md} and the enum {@link Fault} list the same
 * faults: same ids, same names, same order, and the same paper ids.
 */
class FaultCatalogueTest {
    private static final Path CATALOGUE = Path.of("faults", "README.md");
    private static final Pattern HEADING = Pattern.compile("^## (\\d+) · (\\S+)$");
    private static final Pattern PAPER_ID = Pattern.compile("^(?:- )?\\*\\*Paper Table 1 id\\*\\*: *(.*?) *$");
    private static final String NO_PAPER_ID = "—";

    /** One fault's section of the catalogue: its heading and the lines up to the next heading. */
    private record Section(int id, String label, List<String> lines) {
        String entry() {
            return id + " · " + label;
        }
    }

    @Test
    void catalogueListsTheSameIdsAndNamesAsTheCode() throws IOException {
        List<String> inCatalogue = sections().stream().map(Section::entry).toList();
        List<String> inCode = new ArrayList<>();
        for (Fault f : Fault.values()) {
            inCode.add(f.id() + " · " + f.label());
        }
        assertEquals(inCode, inCatalogue, () -> CATALOGUE + " and enum Fault differ: " + differences(inCode, inCatalogue));
    }

    @Test
    void everyFaultHeadingIsWrittenInTheCatalogueForm() throws IOException {
        for (String line : Files.readAllLines(CATALOGUE, StandardCharsets.UTF_8)) {
            if (line.matches("^##\\s*\\d.*")) {
                assertTrue(HEADING.matcher(line).matches(), () -> CATALOGUE + ": the heading \"" + line
                        + "\" is not of the form \"## <id> · <label>\" (one space each side of the middle dot)");
            }
        }
    }

    @Test
    void everyFaultSectionNamesThePaperIdTheCodeGivesIt() throws IOException {
        List<String> problems = new ArrayList<>();
        for (Section section : sections()) {
            Fault fault;
            try {
                fault = Fault.ofId(section.id());
            } catch (IllegalArgumentException e) {
                problems.add("section \"" + section.entry() + "\" names no fault of the code");
                continue;
            }
            List<String> values = new ArrayList<>();
            for (String line : section.lines()) {
                Matcher m = PAPER_ID.matcher(line.strip());
                if (m.matches()) {
                    values.add(m.group(1));
                }
            }
            String expected = fault.paperId().map(String::valueOf).orElse(NO_PAPER_ID);
            if (values.size() != 1) {
                problems.add("section \"" + section.entry() + "\" has " + values.size()
                        + " \"**Paper Table 1 id**\" lines, expected exactly one saying " + expected);
            } else if (!values.get(0).equals(expected)) {
                problems.add("section \"" + section.entry() + "\" gives paper id " + values.get(0)
                        + " but Fault." + fault.name() + ".paperId() is " + describe(fault.paperId())
                        + ", so the catalogue should say " + expected);
            }
        }
        if (!problems.isEmpty()) {
            fail(CATALOGUE + " and enum Fault disagree on paper ids:\n  " + String.join("\n  ", problems));
        }
    }

    private static String describe(Optional<Integer> paperId) {
        return paperId.map(String::valueOf).orElse("empty (not one of the paper's seven)");
    }

    /** The fault sections of the catalogue, in the order they appear. */
    private static List<Section> sections() throws IOException {
        assertTrue(Files.isRegularFile(CATALOGUE),
                () -> "the fault catalogue " + CATALOGUE.toAbsolutePath() + " is missing (tests run from the repository root)");
        List<Section> sections = new ArrayList<>();
        List<String> lines = null;
        for (String line : Files.readAllLines(CATALOGUE, StandardCharsets.UTF_8)) {
            Matcher m = HEADING.matcher(line);
            if (m.matches()) {
                lines = new ArrayList<>();
                sections.add(new Section(Integer.parseInt(m.group(1)), m.group(2), lines));
            } else if (line.startsWith("#")) {
                lines = null; // any other heading ends a fault's section
            } else if (lines != null) {
                lines.add(line);
            }
        }
        return sections;
    }

    /** What is missing, extra or out of place in {@code actual} compared with {@code expected}. */
    private static String differences(List<String> expected, List<String> actual) {
        List<String> parts = new ArrayList<>();
        List<String> missing = new ArrayList<>(expected);
        missing.removeAll(actual);
        if (!missing.isEmpty()) {
            parts.add("in the code but not the catalogue: " + missing);
        }
        List<String> extra = new ArrayList<>(actual);
        extra.removeAll(expected);
        if (!extra.isEmpty()) {
            parts.add("in the catalogue but not the code: " + extra);
        }
        Map<String, Integer> seen = new LinkedHashMap<>();
        for (String entry : actual) {
            seen.merge(entry, 1, Integer::sum);
        }
        seen.forEach((entry, n) -> {
            if (n > 1) {
                parts.add("listed " + n + " times in the catalogue: " + entry);
            }
        });
        if (parts.isEmpty()) {
            parts.add("same entries in a different order; the catalogue must follow id order: " + actual);
        }
        return String.join("; ", parts);
    }
}
