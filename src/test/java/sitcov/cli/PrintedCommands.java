package sitcov.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The sitcov commands a results folder prints for its reader (own-failures.csv's replay column, the
 * commands of report.html and of verdict.txt), as the arguments they run with when typed in a shell
 * opened in the folder: "." and the folder's own files resolved against the folder, the files they
 * write put in {@code scratch}. A fixture of the test that runs every one of them.
 */
final class PrintedCommands {
    private static final String JAR = "java -jar \"$SITCOV_JAR\" ";
    private static final Pattern CODE = Pattern.compile("<code class=\"cmd\">(.*?)</code>");
    private static final Pattern WORD = Pattern.compile("<span>(.*?)</span>");
    private static final Set<String> WRITES = Set.of("--png", "--gif", "--out", "--trace");

    private PrintedCommands() {
    }

    /** Every command the folder prints that runs sitcov, each as it would run from inside the folder. */
    static List<List<String>> of(Path folder, Path scratch) throws IOException {
        List<String> printed = new ArrayList<>();
        List<String> own = Files.readAllLines(folder.resolve("own-failures.csv"));
        int replay = List.of(own.get(0).split(",")).indexOf("replay");
        for (String row : own.subList(1, own.size())) {
            printed.add(row.split(",", -1)[replay]);
        }
        Matcher code = CODE.matcher(Files.readString(folder.resolve("report.html")));
        while (code.find()) {
            List<String> words = new ArrayList<>();
            Matcher w = WORD.matcher(code.group(1));
            while (w.find()) {
                words.add(w.group(1).replace("&quot;", "\"").replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&"));
            }
            printed.add(String.join(" ", words));
        }
        for (String line : Files.readAllLines(folder.resolve("verdict.txt"))) {
            int at = line.indexOf(JAR);
            if (at >= 0) {
                printed.add(line.substring(at).replaceAll("['.)]*$", ""));
            }
        }
        List<List<String>> commands = new ArrayList<>();
        for (String p : printed) {
            if (p.startsWith(JAR)) {
                List<String> args = arguments(shellWords(p.substring(JAR.length())), folder, scratch);
                if (args.get(0).equals("replay") && !args.contains("--png")) {
                    // its picture goes where it is run from: here, the scratch folder rather than the checkout
                    args.addAll(List.of("--png", scratch.resolve("replay-" + commands.size() + ".png").toString()));
                }
                commands.add(args);
            }
        }
        return commands;
    }

    /**
     * The command a refusal's message advises (the words after {@code lead} to the end of its line, less the
     * sentence's full stop), as arguments to run.
     */
    static List<String> advised(String message, String lead) {
        String line = message.lines().filter(l -> l.contains(lead)).findFirst()
                .orElseThrow(() -> new AssertionError("no advice '" + lead + "' in: " + message));
        String command = line.substring(line.indexOf(lead) + lead.length());
        return shellWords(command.endsWith(".") ? command.substring(0, command.length() - 1) : command);
    }

    private static List<String> arguments(List<String> words, Path folder, Path scratch) {
        List<String> args = new ArrayList<>();
        for (int i = 0; i < words.size(); i++) {
            String w = words.get(i);
            if (i > 0 && WRITES.contains(words.get(i - 1))) {
                args.add(scratch.resolve(w).toString());
            } else if (w.equals(".") || w.startsWith("situations/") || w.startsWith("recordings/")) {
                args.add(folder.resolve(w).normalize().toString());
            } else {
                args.add(w);
            }
        }
        return args;
    }

    /** The words a POSIX shell makes of {@code line}: split at white space, quotes kept together and removed, a backslash outside quotes escaping the next character. */
    static List<String> shellWords(String line) {
        List<String> words = new ArrayList<>();
        StringBuilder word = new StringBuilder();
        boolean inWord = false;
        char quote = 0;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (quote != 0) {
                if (c == quote) {
                    quote = 0;
                } else {
                    word.append(c);
                }
            } else if (c == '\\' && i + 1 < line.length()) {
                word.append(line.charAt(++i));
                inWord = true;
            } else if (c == '\'' || c == '"') {
                quote = c;
                inWord = true;
            } else if (Character.isWhitespace(c)) {
                if (inWord) {
                    words.add(word.toString());
                    word.setLength(0);
                    inWord = false;
                }
            } else {
                word.append(c);
                inWord = true;
            }
        }
        if (inWord) {
            words.add(word.toString());
        }
        return words;
    }
}
