package sitcov.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Properties;
import java.util.Set;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import sitcov.control.ControllerFactory;
import sitcov.control.ControllerSource;
import sitcov.judge.VersionJudge;
import sitcov.judge.VersionVerdict;
import sitcov.results.IoReason;
import sitcov.results.OutputFile;
import sitcov.world.MapGenerator;

/**
 * {@code versions}: a controller's variants (its next version, a build with a planted bug) against
 * the reference controller, map by map, by the differential oracle (README, "Test your own
 * controller"). Writes versions.csv and verdict.txt into a results folder.
 */
final class VersionsCommand implements Command {
    static final int MAX_MAPS = 1_000_000;

    @Override
    public String name() {
        return "versions";
    }

    @Override
    public String synopsis() {
        return "PRESET | --reference CONTROLLER --variants CONTROLLER[;CONTROLLER…]  [--maps N] [--seed S0] [--threads T] [--fork on|off] [--out DIR]";
    }

    @Override
    public String summary() {
        return "compare controller versions map by map: where does a variant fail that the reference did not?";
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        Options options = Options.parse(name(), args, Set.of("--reference", "--variants", "--maps", "--seed", "--threads",
                "--fork", "--out"), Set.of());
        VersionsPlan plan = plan(options);
        int threads = options.threads(err);
        boolean fork = options.forks();
        Path folder = options.value("--out").map(Path::of)
                .orElse(Path.of("target", "results", plan.name() + "-seed" + plan.firstSeed()));
        if (Files.exists(folder) && !isEmptyFolder(folder)) {
            throw new UsageException("versions: --out " + Options.shown(folder) + " exists and is not an empty folder;"
                    + " results never overwrite others: name a new folder.");
        }
        List<ControllerSource> sources = new ArrayList<>();
        try {
            // every controller is started and handshaken before the folder is made: one that cannot leaves nothing
            sources.add(Controllers.open(plan.reference(), folder, "controller-reference"));
            for (int v = 0; v < plan.variants().size(); v++) {
                sources.add(Controllers.open(plan.variants().get(v), folder, "controller-variant-" + (v + 1)));
            }
            try {
                Files.createDirectories(folder);
            } catch (IOException e) {
                throw new UsageException("versions: cannot create " + folder + ": " + IoReason.of(e, folder) + ".");
            }
            List<List<VersionVerdict>> judged = judge(plan, sources, threads, fork);
            String csv = VersionsReport.csv(plan, judged);
            String verdict = VersionsReport.verdict(plan, judged);
            OutputFile.writeString(folder.resolve("versions.csv"), csv);
            OutputFile.writeString(folder.resolve("verdict.txt"), verdict);
            out.print(verdict);
            out.println("Results in " + folder);
            return ExitCode.OK;
        } catch (IOException e) {
            err.println("sitcov: versions: cannot write into " + folder + ": " + IoReason.of(e, folder) + ".");
            return ExitCode.FAILURE;
        } finally {
            sources.forEach(ControllerSource::close);
        }
    }

    private static List<List<VersionVerdict>> judge(VersionsPlan plan, List<ControllerSource> sources, int threads,
                                                    boolean fork) {
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        try {
            List<Future<List<VersionVerdict>>> futures = new ArrayList<>();
            for (int i = 0; i < plan.maps(); i++) {
                long seed = plan.firstSeed() + i;
                futures.add(pool.submit(() -> {
                    List<ControllerFactory> variants = new ArrayList<>();
                    for (ControllerSource s : sources.subList(1, sources.size())) {
                        variants.add(s.forThisThread());
                    }
                    ControllerFactory reference = sources.get(0).forThisThread();
                    return VersionJudge.judge(MapGenerator.generate(seed), seed, fork ? reference : reference.unforked(),
                            variants);
                }));
            }
            List<List<VersionVerdict>> all = new ArrayList<>();
            for (Future<List<VersionVerdict>> f : futures) {
                all.add(f.get());
            }
            return all;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause().getMessage(), e.getCause());
        } finally {
            pool.shutdownNow();
        }
    }

    private static VersionsPlan plan(Options options) throws UsageException {
        Properties p = new Properties();
        String name = "versions";
        if (options.positional().size() == 1) {
            String named = options.positional().get(0);
            Path shipped = Path.of("experiments", "controllers", named + ".properties");
            Path file = Files.isRegularFile(shipped) ? shipped : Path.of(named);
            if (!Files.isRegularFile(file)) {
                throw new UsageException("versions: no preset '" + named + "': neither a file nor " + shipped
                        + "; the shipped one is byo-controller, or give --reference and --variants.");
            }
            try {
                p.load(new java.io.StringReader(Files.readString(file, StandardCharsets.UTF_8)));
            } catch (IOException | IllegalArgumentException e) {
                throw new UsageException("versions: cannot read the preset " + file + ": " + e.getMessage() + ".");
            }
            for (String key : p.stringPropertyNames()) {
                if (!Set.of("name", "description", "reference", "variants", "maps", "master_seed").contains(key)) {
                    throw new UsageException("versions: " + file + ": unknown key '" + key + "'; the keys are [description,"
                            + " maps, master_seed, name, reference, variants].");
                }
            }
            name = p.getProperty("name", file.getFileName().toString().replaceFirst("\\.properties$", "")).strip();
        } else if (!options.positional().isEmpty()) {
            throw new UsageException("versions: name one preset, or give --reference and --variants.");
        }
        options.value("--reference").ifPresent(v -> p.setProperty("reference", v));
        options.value("--variants").ifPresent(v -> p.setProperty("variants", v));
        String reference = p.getProperty("reference", "").strip();
        String variants = p.getProperty("variants", "").strip();
        if (reference.isEmpty() || variants.isEmpty()) {
            throw new UsageException("versions: name the reference controller and its variants, e.g. --reference builtin"
                    + " --variants 'builtin:16;builtin:17', or a preset with reference= and variants=.");
        }
        List<String> variantList = new ArrayList<>();
        for (String v : Arrays.stream(variants.split(";")).map(String::strip).toList()) {
            variantList.add(Controllers.check(v));
        }
        Controllers.check(reference);
        int maps = options.count("--maps", 1, MAX_MAPS).orElse(countOf(p.getProperty("maps", "100")));
        long seed = options.seed("--seed").orElse(Long.parseLong(p.getProperty("master_seed", "1").strip()));
        return new VersionsPlan(name, reference, variantList, maps, seed);
    }

    private static int countOf(String text) throws UsageException {
        try {
            int n = Integer.parseInt(text.strip());
            if (n >= 1 && n <= MAX_MAPS) {
                return n;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        throw new UsageException("versions: maps= needs a whole number from 1 to " + MAX_MAPS + ", not '" + text.strip() + "'.");
    }

    private static boolean isEmptyFolder(Path folder) {
        try (var list = Files.list(folder)) {
            return list.findAny().isEmpty();
        } catch (IOException e) {
            return false;
        }
    }
}
