package sitcov.results;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The schema of one CSV table: its column list, the single place that both writes the table and
 * reads it back (experiments/README.md, "The results folder"). Rows are written by column name and read by the
 * names of the file's own header, so a folder written by another version of sitcov is either read
 * correctly or refused with a message naming the column it lacks or does not know; it is never
 * misread by position.
 */
public final class Columns {
    private final List<String> names;
    /** Columns a file written before they existed may lack: read as blank. */
    private final Set<String> optional;
    private final Map<String, Integer> index = new HashMap<>();

    public Columns(List<String> names) {
        this(names, Set.of());
    }

    /** A table whose columns {@code optional} were added later: a file without them reads them blank. */
    public Columns(List<String> names, Set<String> optional) {
        this.names = List.copyOf(names);
        this.optional = Set.copyOf(optional);
        for (int i = 0; i < this.names.size(); i++) {
            if (index.put(this.names.get(i), i) != null) {
                throw new IllegalArgumentException("the column " + this.names.get(i) + " is listed twice");
            }
        }
    }

    public static Columns of(String... names) {
        return new Columns(List.of(names));
    }

    public List<String> names() {
        return names;
    }

    /** The header line, without '\n'. */
    public String header() {
        return String.join(",", names);
    }

    /** A new row to fill by column name. */
    public Row row() {
        return new Row();
    }

    /** One row being written: every column must be given a value before {@link #line()}. */
    public final class Row {
        private final String[] values = new String[names.size()];

        public Row set(String column, Object value) {
            values[at(column)] = String.valueOf(value);
            return this;
        }

        /** Leaves every column not given a value blank: for tables whose rows of one kind lack another kind's columns. */
        public Row blankRest() {
            for (int i = 0; i < values.length; i++) {
                if (values[i] == null) {
                    values[i] = "";
                }
            }
            return this;
        }

        /** The row without its '\n', for a file written whole from a list of lines. */
        public String text() {
            String line = line();
            return line.substring(0, line.length() - 1);
        }

        /** The row as a line ending in '\n'. */
        public String line() {
            for (int i = 0; i < values.length; i++) {
                if (values[i] == null) {
                    throw new IllegalStateException("no value for the column " + names.get(i));
                }
            }
            return String.join(",", values) + "\n";
        }
    }

    private int at(String column) {
        Integer i = index.get(column);
        if (i == null) {
            throw new IllegalArgumentException("the table has no column " + column);
        }
        return i;
    }

    /**
     * How a file's header places this table's columns.
     *
     * @param fix what the user can do when the header does not fit, ending the message
     * @throws IllegalArgumentException naming the file, and every column it lacks or does not know
     */
    public Layout layout(String header, String source, String fix) {
        List<String> found = List.of(header.split(",", -1));
        Set<String> missing = new LinkedHashSet<>(names);
        found.forEach(missing::remove);
        missing.removeAll(optional);
        Set<String> unknown = new LinkedHashSet<>(found);
        names.forEach(unknown::remove);
        Set<String> twice = new LinkedHashSet<>();
        Set<String> seen = new java.util.HashSet<>();
        for (String f : found) {
            if (!seen.add(f)) {
                twice.add(f);
            }
        }
        List<String> problems = new ArrayList<>();
        if (!missing.isEmpty()) {
            problems.add("lacks the column" + plural(missing) + " this sitcov reads");
        }
        if (!unknown.isEmpty()) {
            problems.add("has the column" + plural(unknown) + " this sitcov does not know");
        }
        if (!twice.isEmpty()) {
            problems.add("has the column" + plural(twice) + " twice");
        }
        if (!problems.isEmpty()) {
            throw new IllegalArgumentException(source + ":1: the header " + String.join(" and ", problems)
                    + " (it was written by another version of sitcov, or for another experiment); " + fix);
        }
        int[] position = new int[names.size()];
        for (int i = 0; i < names.size(); i++) {
            position[i] = found.indexOf(names.get(i));
        }
        return new Layout(position, found.size());
    }

    private static String plural(Set<String> columns) {
        return (columns.size() == 1 ? " '" : "s '") + String.join("', '", columns) + "'";
    }

    /** A file's header, matched to this table's columns. */
    public final class Layout {
        private final int[] position;
        /** The file's columns. */
        private final int width;

        private Layout(int[] position, int width) {
            this.position = position;
            this.width = width;
        }

        /**
         * One line of the file, split into its columns.
         *
         * @throws IllegalArgumentException if it has not one value per column (the caller names the line)
         */
        public Line split(String line) {
            String[] values = line.split(",", -1);
            if (values.length != width) {
                throw new IllegalArgumentException("expected " + width + " columns, found " + values.length);
            }
            return new Line(values, this);
        }

        private String get(String[] values, String column) {
            int p = position[at(column)];
            return p < 0 ? "" : values[p];
        }
    }

    /** A line read from a file: its values by column name. */
    public static final class Line {
        private final String[] values;
        private final Layout layout;

        private Line(String[] values, Layout layout) {
            this.values = values;
            this.layout = layout;
        }

        public String get(String column) {
            return layout.get(values, column);
        }

        public int integer(String column) {
            return Integer.parseInt(get(column));
        }

        public long longValue(String column) {
            return Long.parseLong(get(column));
        }

        public double decimal(String column) {
            return Double.parseDouble(get(column));
        }

        public boolean bool(String column) {
            return switch (get(column)) {
                case "true" -> true;
                case "false" -> false;
                default -> throw new IllegalArgumentException("expected true or false in " + column + ", found '"
                        + get(column) + "'");
            };
        }
    }
}
