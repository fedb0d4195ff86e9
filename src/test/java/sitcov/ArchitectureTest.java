package sitcov;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** Enforces the package dependency table of the README (Map of the repository) by reading the imports of src/main. */
class ArchitectureTest {

    private static final Path MAIN = Path.of("src", "main", "java", "sitcov");
    private static final Set<String> BELOW_REPORT = Set.of(
            "engine", "geom", "stats", "world", "faults", "vehicles", "oracle", "coverage", "experiment");

    /** Which sitcov packages each package may import (its own is always allowed). */
    private static final Map<String, Set<String>> ALLOWED = Map.ofEntries(
            Map.entry("engine", Set.of()),
            Map.entry("geom", Set.of()),
            Map.entry("stats", Set.of()),
            Map.entry("world", Set.of("engine", "geom")),
            Map.entry("faults", Set.of("engine")),
            Map.entry("vehicles", Set.of("world", "faults", "engine", "geom")),
            Map.entry("oracle", Set.of("vehicles", "world", "engine", "geom")),
            Map.entry("coverage", Set.of("world", "geom")),
            Map.entry("experiment", Set.of("engine", "geom", "stats", "world", "faults", "vehicles", "oracle",
                    "coverage")),
            Map.entry("report", Set.of("engine", "geom", "stats", "world", "faults", "vehicles", "oracle", "coverage",
                    "experiment")),
            Map.entry("cli", Set.of("engine", "geom", "stats", "world", "faults", "vehicles", "oracle", "coverage",
                    "experiment", "report", "viewer")),
            Map.entry("viewer", Set.of("engine", "geom", "stats", "world", "faults", "vehicles", "oracle", "coverage",
                    "experiment", "report")));

    private static final Pattern SITCOV_REFERENCE = Pattern.compile("\\bsitcov\\.([a-z]+)\\.");
    private static final Pattern GUI_REFERENCE = Pattern.compile("\\b(java\\.awt|javax\\.swing)\\b");

    @Test
    void everyPackageImportsOnlyWhatTheDependencyTableAllows() throws IOException {
        List<String> violations = new ArrayList<>();
        for (Path file : sources()) {
            String pkg = packageOf(file);
            Set<String> allowed = ALLOWED.get(pkg);
            if (allowed == null) {
                violations.add(file + ": package sitcov." + pkg + " is not in the dependency table of the README (Map of the repository)");
                continue;
            }
            for (String line : importLines(file)) {
                Matcher m = SITCOV_REFERENCE.matcher(line);
                while (m.find()) {
                    String used = m.group(1);
                    if (!used.equals(pkg) && !allowed.contains(used)) {
                        violations.add(file + ": sitcov." + pkg + " may not use sitcov." + used + " (" + line.trim() + ")");
                    }
                }
            }
        }
        assertEquals(List.of(), violations);
    }

    @Test
    void noPackageBelowReportTouchesAwtOrSwing() throws IOException {
        List<String> violations = new ArrayList<>();
        for (Path file : sources()) {
            if (!BELOW_REPORT.contains(packageOf(file)) && ALLOWED.containsKey(packageOf(file))) {
                continue;
            }
            List<String> lines = Files.readAllLines(file);
            for (int i = 0; i < lines.size(); i++) {
                if (GUI_REFERENCE.matcher(lines.get(i)).find()) {
                    violations.add(file + ":" + (i + 1) + ": " + lines.get(i).trim());
                }
            }
        }
        assertEquals(List.of(), violations);
    }

    @Test
    void theScanSeesTheSources() throws IOException {
        assertTrue(sources().size() >= 5, "the architecture test found too few sources under " + MAIN.toAbsolutePath());
    }

    private static List<Path> sources() throws IOException {
        try (Stream<Path> walk = Files.walk(MAIN)) {
            return walk.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
    }

    private static String packageOf(Path file) {
        Path relative = MAIN.relativize(file);
        return relative.getNameCount() < 2 ? "" : relative.getName(0).toString();
    }

    /** Import lines, plus any fully qualified sitcov.x. reference in code, so neither escapes the rule. */
    private static List<String> importLines(Path file) throws IOException {
        return Files.readAllLines(file).stream()
                .filter(l -> !l.trim().startsWith("package "))
                .filter(l -> !l.trim().startsWith("*") && !l.trim().startsWith("//") && !l.trim().startsWith("/*"))
                .filter(l -> l.contains("sitcov."))
                .toList();
    }
}
