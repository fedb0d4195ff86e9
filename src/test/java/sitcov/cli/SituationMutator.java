package sitcov.cli;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.random.RandomGenerator;

/** Makes a broken variant of a situation file's text, the way a hand edit or a damaged copy would. */
final class SituationMutator {
    private static final String[] NUMBERS = {"0", "-1", "-0", "3", "6", "9.5", "23", "99.999", "100", "150", "199.9",
        "200", "250", "-50", "1e308", "-1e308", "1e6", "1000.0001", "NaN", "Infinity", "inf", "1e-300", "9999999999999",
        "2147483648", "abc", "", "0x10", "1,5"};
    private static final String[] WORDS = {"NORTH", "EAST", "SOUTH", "WEST", "NORTH_SOUTH", "EAST_WEST", "UP", "road",
        "junction", "parked-car", "target", "car-start", "moving-car", "end", "seed", "omission", "generation", "#"};

    private SituationMutator() {
    }

    static String mutate(String text, RandomGenerator random) {
        List<String> lines = new ArrayList<>(Arrays.asList(text.split("\n", -1)));
        int edits = 1 + random.nextInt(3);
        for (int e = 0; e < edits && !lines.isEmpty(); e++) {
            int at = random.nextInt(lines.size());
            switch (random.nextInt(10)) {
                case 0 -> lines.remove(at);
                case 1 -> lines.add(at, lines.get(random.nextInt(lines.size())));
                case 2 -> lines.set(at, replaceWord(lines.get(at), NUMBERS[random.nextInt(NUMBERS.length)], random));
                case 3 -> lines.set(at, replaceWord(lines.get(at), WORDS[random.nextInt(WORDS.length)], random));
                case 4 -> lines.set(at, nudge(lines.get(at), random));
                case 5 -> {
                    int other = random.nextInt(lines.size());
                    String t = lines.get(at);
                    lines.set(at, lines.get(other));
                    lines.set(other, t);
                }
                case 6 -> {
                    // a flood of one element, past any sane count
                    String line = lines.get(at);
                    for (int i = 0; i < 150 + random.nextInt(150); i++) {
                        lines.add(at, line);
                    }
                }
                case 7 -> lines.set(0, "\uFEFF" + lines.get(0));
                case 8 -> {
                    String joined = String.join("\n", lines);
                    return joined.substring(0, random.nextInt(Math.max(1, joined.length())));
                }
                default -> lines.set(at, lines.get(at) + " " + NUMBERS[random.nextInt(NUMBERS.length)]);
            }
        }
        return String.join("\n", lines);
    }

    private static String replaceWord(String line, String word, RandomGenerator random) {
        String[] w = line.split(" ", -1);
        w[random.nextInt(w.length)] = word;
        return String.join(" ", w);
    }

    /** Moves one number of the line a little, so the file stays well formed but may break the world's rules. */
    private static String nudge(String line, RandomGenerator random) {
        String[] w = line.split(" ", -1);
        int i = random.nextInt(w.length);
        try {
            double v = Double.parseDouble(w[i]);
            w[i] = Double.toString(v + (random.nextBoolean() ? 1 : -1) * (0.5 + random.nextInt(30)));
        } catch (NumberFormatException e) {
            return line;
        }
        return String.join(" ", w);
    }
}
