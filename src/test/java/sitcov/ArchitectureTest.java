package sitcov;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** Enforces the package dependency table of src/README.md, "Map of the repository", by reading the imports of src/main. */
class ArchitectureTest {

    private static final Path MAIN = Path.of("src", "main", "java", "sitcov");
    /**
     * The simulated world and what it is made of: below every job that runs or reports an experiment.
     * Not the builtin car: it is one controller among others, plugged in by those that name controllers.
     */
    private static final Set<String> SIMULATION = Set.of(
            "engine", "geom", "stats", "world", "control", "faults", "sensors", "vehicles", "oracle", "coverage", "seam");

    /** The only packages that may name the builtin car: the command line and the controller registry. */
    private static final Set<String> PLUGGING_IN_THE_BUILTIN_CAR = Set.of("cli", "protocol");

    /** Packages that compute and write text only: no drawing, no window. */
    private static final Set<String> HEADLESS = union(SIMULATION,
            "builtin", "judge", "experiment", "drivers", "analysis", "verdict", "results", "export", "protocol", "estimate", "recording");

    /**
     * Which sitcov packages each package may import (its own is always allowed). Every arrow points down:
     * {@link #theTableHasNoLoop()} holds the table itself to that.
     */
    private static final Map<String, Set<String>> ALLOWED = Map.ofEntries(
            Map.entry("engine", Set.of()),
            Map.entry("geom", Set.of()),
            Map.entry("stats", Set.of()),
            Map.entry("world", Set.of("engine", "geom")),
            Map.entry("control", Set.of("world", "engine", "geom")),
            // the seeded faults, and the factory of a controller that is handed a run's faults
            Map.entry("faults", Set.of("control", "engine")),
            // what the world offers every controller: camera, LIDAR, radar tracks
            Map.entry("sensors", Set.of("control", "world", "geom")),
            Map.entry("vehicles", Set.of("control", "sensors", "world", "engine", "geom")),
            // the builtin car: a controller that uses the sensors as any other may, with its seeded faults
            Map.entry("builtin", Set.of("control", "faults", "sensors", "vehicles", "world", "geom")),
            // the controller protocol and registry: a controller program behind the seam, the builtin car served over it
            Map.entry("protocol", Set.of("control", "builtin", "vehicles", "world", "faults", "engine", "geom")),
            // seam faults: any controller's observation and command distorted between it and the world
            Map.entry("seam", Set.of("control", "engine", "sensors", "vehicles", "world", "geom")),
            Map.entry("oracle", Set.of("control", "vehicles", "world", "engine", "geom")),
            Map.entry("coverage", Set.of("world", "geom")),
            // judging one map: a run, its twin with a fault, the verdict
            Map.entry("judge", Set.of("engine", "geom", "stats", "world", "faults", "control", "vehicles", "oracle",
                    "seam")),
            // the experiment engine: it knows drivers only through the Driver interface
            Map.entry("experiment", union(SIMULATION, "judge")),
            Map.entry("drivers", union(SIMULATION, "judge", "experiment")),
            // the analysis reads what an experiment recorded and knows no driver by name
            Map.entry("analysis", union(SIMULATION, "judge", "experiment")),
            Map.entry("verdict", union(SIMULATION, "judge", "experiment", "analysis")),
            Map.entry("results", union(SIMULATION, "judge", "experiment", "analysis")),
            // a failure rate estimated: runs of the generator's maps, weighted by their traced draws; stress-search's stress
            Map.entry("estimate", union(SIMULATION, "judge", "drivers", "results")),
            // maps, situations and recorded runs in the ASAM formats: a run of the builtin car is all it needs
            Map.entry("export", union(SIMULATION, "judge")),
            // a results folder's recordings: the commands of its failing runs, replayed without their controller
            Map.entry("recording", union(SIMULATION, "judge", "experiment", "results")),
            Map.entry("render", union(SIMULATION, "judge", "experiment", "results", "recording")),
            Map.entry("figures", union(SIMULATION, "judge", "experiment", "analysis", "verdict", "results", "render")),
            Map.entry("report", union(SIMULATION, "judge", "experiment", "analysis", "verdict", "results", "render",
                    "figures", "recording")),
            Map.entry("viewer", union(SIMULATION, "judge", "experiment", "analysis", "verdict", "results", "render",
                    "figures", "report", "recording")),
            Map.entry("cli", union(SIMULATION, "judge", "experiment", "drivers", "analysis", "verdict", "results",
                    "export", "render", "figures", "report", "viewer", "protocol", "builtin", "estimate", "recording")));

    private static final Pattern SITCOV_REFERENCE = Pattern.compile("\\bsitcov\\.([a-z]+)\\.");
    private static final Pattern GUI_REFERENCE = Pattern.compile("\\b(java\\.awt|javax\\.swing)\\b");

    @Test
    void everyPackageImportsOnlyWhatTheDependencyTableAllows() throws IOException {
        List<String> violations = new ArrayList<>();
        for (Path file : sources()) {
            String pkg = packageOf(file);
            Set<String> allowed = ALLOWED.get(pkg);
            if (allowed == null) {
                violations.add(file + ": package sitcov." + pkg + " is not in the dependency table of src/README.md (Map of the repository)");
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
    void noHeadlessPackageTouchesAwtOrSwing() throws IOException {
        List<String> violations = new ArrayList<>();
        for (Path file : sources()) {
            if (!HEADLESS.contains(packageOf(file)) && ALLOWED.containsKey(packageOf(file))) {
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
    void theBuiltinCarIsAPlugInOnlyTheCommandLineAndTheRegistryName() {
        Set<String> naming = new TreeSet<>();
        ALLOWED.forEach((pkg, allowed) -> {
            if (allowed.contains("builtin")) {
                naming.add(pkg);
            }
        });
        assertEquals(new TreeSet<>(PLUGGING_IN_THE_BUILTIN_CAR), naming);
        assertTrue(!ALLOWED.get("control").contains("faults"), "the seam knows no seeded faults");
    }

    @Test
    void theTableHasNoLoop() {
        // peel off, round by round, the packages that may use only packages already peeled: what is
        // left when nothing more comes off allows, through some chain, a use of itself
        Set<String> peeled = new HashSet<>();
        boolean progress = true;
        while (progress) {
            progress = false;
            for (Map.Entry<String, Set<String>> e : ALLOWED.entrySet()) {
                if (!peeled.contains(e.getKey()) && peeled.containsAll(e.getValue())) {
                    peeled.add(e.getKey());
                    progress = true;
                }
            }
        }
        Set<String> looping = new TreeSet<>(ALLOWED.keySet());
        looping.removeAll(peeled);
        assertEquals(Set.of(), looping, "packages whose allowed imports lead back to themselves");
    }

    @Test
    void theScanSeesTheSources() throws IOException {
        assertTrue(sources().size() >= 5, "the architecture test found too few sources under " + MAIN.toAbsolutePath());
    }

    private static Set<String> union(Set<String> base, String... more) {
        Set<String> all = new HashSet<>(base);
        all.addAll(List.of(more));
        return Set.copyOf(all);
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
