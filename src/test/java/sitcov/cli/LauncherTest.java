package sitcov.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The launcher {@code experiments/sitcov} runs the jar it is given (SITCOV_JAR: here a jar of the compiled classes,
 * as {@code mvn package} makes one), passing every argument and the exit code through; the program's usage names it.
 */
class LauncherTest {
    private static final Path LAUNCHER = Path.of(Main.LAUNCHER);
    private static final Path SH = Path.of("/bin/sh");

    @TempDir
    Path dir;

    @Test
    void theLauncherIsAnExecutableShellScript() throws IOException {
        assertTrue(Files.isExecutable(LAUNCHER), LAUNCHER + " is executable");
        assertTrue(Files.readString(LAUNCHER, StandardCharsets.UTF_8).startsWith("#!/bin/sh\n"));
    }

    @Test
    void itRunsTheJarWithTheArgumentsAndHandsBackTheExitCode() throws Exception {
        assumeTrue(Files.isExecutable(SH), "a POSIX sh runs the launcher");
        Path jar = jarOfTheClasses();
        Result version = launch(jar, "--version");
        assertEquals(0, version.code(), version.out());
        assertTrue(version.out().matches("sitcov \\d+\\.\\d+\\.\\d+(-SNAPSHOT)?\\R"), version.out());
        Result help = launch(jar, "map", "--help");
        assertTrue(help.out().startsWith("Usage: experiments/sitcov map "), help.out());
        Result bad = launch(jar, "--frobnicate", "with spaces");
        assertEquals(ExitCode.USAGE, bad.code(), bad.out());
        assertTrue(bad.out().contains("Run 'experiments/sitcov --help' for usage."), bad.out());
    }

    private record Result(int code, String out) {
    }

    private Result launch(Path jar, String... args) throws Exception {
        List<String> command = new java.util.ArrayList<>(List.of(SH.toString(), LAUNCHER.toString()));
        command.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().put("SITCOV_JAR", jar.toString());
        pb.environment().put("JAVA", Path.of(System.getProperty("java.home"), "bin", "java").toString());
        Process p = pb.start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        return new Result(p.waitFor(), out);
    }

    /** A runnable jar of target/classes, with sitcov.cli.Main as its main class. */
    private Path jarOfTheClasses() throws IOException {
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().getPath());
        Manifest manifest = new Manifest();
        manifest.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        manifest.getMainAttributes().put(Attributes.Name.MAIN_CLASS, Main.class.getName());
        Path jar = dir.resolve("sitcov.jar");
        try (OutputStream file = Files.newOutputStream(jar); JarOutputStream out = new JarOutputStream(file, manifest);
             Stream<Path> all = Files.walk(classes)) {
            for (Path p : all.filter(Files::isRegularFile).sorted().toList()) {
                out.putNextEntry(new JarEntry(classes.relativize(p).toString().replace('\\', '/')));
                Files.copy(p, out);
                out.closeEntry();
            }
        }
        return jar;
    }
}
