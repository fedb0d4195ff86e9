package sitcov.recording;

import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import sitcov.control.ControllerFailure;
import sitcov.control.Sensor;
import sitcov.geom.Compass;
import sitcov.oracle.Outcome;
import sitcov.vehicles.CommandLog;

/**
 * A recording's lines, before compression and without the check line (RECORDINGS.md). Numbers are
 * written in Java's round-trip form, so every command comes back bit for bit; a number that is not
 * finite is written {@code NaN}, {@code Infinity} or {@code -Infinity}, as Python's json module does.
 */
final class RecordingText {
    private RecordingText() {
    }

    static String format(Recording r) {
        CommandLog log = r.commands();
        StringBuilder out = new StringBuilder(32 * log.ticks() + 256);
        Recording.RunKey k = r.key();
        out.append("{\"sitcov_recording\":").append(RecordingFile.FORMAT).append(",\"replication\":").append(k.replication())
                .append(",\"driver\":");
        quote(out, k.driver());
        out.append(",\"map_index\":").append(k.mapIndex()).append(",\"variant\":").append(k.variant())
                .append(",\"external_seed\":").append(r.externalSeed()).append(",\"internal_seed\":").append(r.internalSeed())
                .append(",\"outcome\":\"").append(r.outcome().name()).append("\",\"ticks\":").append(r.ticks())
                .append(",\"sensors\":[");
        int written = 0;
        for (Sensor sensor : log.sensors()) {
            out.append(written++ == 0 ? "" : ",").append('"').append(sensor.wireName()).append('"');
        }
        out.append("]}\n");
        int clamp = 0;
        int request = 0;
        int report = 0;
        for (int t = 0; t < log.ticks(); t++) {
            // no tick number: the line's place says it, and a car standing still compresses to nothing
            if (t == log.failedAt()) {
                out.append("{\"failure\":\"").append(log.failureKind().name()).append("\",\"message\":");
                quote(out, log.failureMessage());
                out.append("}\n");
                continue;
            }
            out.append("{\"v\":");
            number(out, log.speed(t));
            out.append(",\"s\":");
            number(out, log.steering(t));
            if (clamp < log.clamps() && log.clampTick(clamp) == t) {
                out.append(",\"asked\":[");
                number(out, log.askedSpeed(clamp));
                out.append(',');
                number(out, log.askedSteering(clamp++));
                out.append(']');
            }
            int end = request;
            while (end < log.requests() && log.requestTick(end) == t) {
                end++;
            }
            requests(out, log, request, end, false);
            requests(out, log, request, end, true);
            request = end;
            if (report < log.reports() && log.reportTick(report) == t) {
                report(out, log.report(report++));
            }
            out.append("}\n");
        }
        return out.toString();
    }

    /** Appends requests {@code from} (inclusive) to {@code to} (exclusive): the claims, or the releases. */
    private static void requests(StringBuilder out, CommandLog log, int from, int to, boolean claims) {
        boolean any = false;
        for (int i = from; i < to; i++) {
            if (log.isClaim(i) == claims) {
                out.append(any ? "," : claims ? ",\"claim\":[" : ",\"release\":[").append(log.requestJunction(i));
                any = true;
            }
        }
        if (any) {
            out.append(']');
        }
    }

    private static void report(StringBuilder out, CommandLog.Report r) {
        out.append(",\"report\":{\"overtaking\":").append(r.overtaking()).append(",\"crossing_junction\":")
                .append(r.crossingJunction()).append(",\"waiting_at_junction\":").append(r.waitingAtJunction());
        text(out, "lane", r.lane() == null ? null : r.lane().name());
        text(out, "stage", r.stage());
        text(out, "limited_by", r.limitedBy());
        text(out, "steered_by", r.steeredBy());
        out.append('}');
    }

    private static void text(StringBuilder out, String name, String value) {
        if (value != null) {
            out.append(",\"").append(name).append("\":");
            quote(out, value);
        }
    }

    private static void number(StringBuilder out, double v) {
        out.append(Double.isFinite(v) ? Double.toString(v) : Double.isNaN(v) ? "NaN" : v > 0 ? "Infinity" : "-Infinity");
    }

    private static void quote(StringBuilder out, String s) {
        out.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                case '\r' -> out.append("\\r");
                case '\t' -> out.append("\\t");
                default -> {
                    if (c < 0x20) {
                        out.append(String.format("\\u%04x", (int) c));
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        out.append('"');
    }

    /** The recording {@code body} holds (its check verified); {@code source} names it in errors. */
    static Recording parse(String body, String source) {
        String[] lines = body.split("\n", -1);
        int n = lines.length - 1; // the body ends in a newline
        if (n < 1) {
            throw malformed(source, 1, "it has no header");
        }
        try {
            Map<String, Object> h = object(lines[0], source, 1);
            if (number(h, "sitcov_recording", source, 1) != RecordingFile.FORMAT) {
                throw malformed(source, 1, "it is in format " + h.get("sitcov_recording") + "; this sitcov reads format "
                        + RecordingFile.FORMAT);
            }
            Recording.RunKey key = new Recording.RunKey((int) number(h, "replication", source, 1),
                    (String) h.get("driver"), (int) number(h, "map_index", source, 1), (int) number(h, "variant", source, 1));
            Outcome outcome = Outcome.valueOf((String) h.get("outcome"));
            CommandLog log = new CommandLog();
            if (h.containsKey("sensors")) {
                log.sensors(sensors(h.get("sensors"), source));
            } // a recording written before sensors were recorded: its log keeps what a program takes by default
            for (int i = 1; i < n; i++) {
                tick(log, object(lines[i], source, i + 1), source, i + 1);
            }
            return new Recording(key, number(h, "external_seed", source, 1), number(h, "internal_seed", source, 1),
                    outcome, number(h, "ticks", source, 1), log);
        } catch (ClassCastException | NullPointerException | IllegalArgumentException e) {
            if (e instanceof Malformed m) {
                throw m;
            }
            throw malformed(source, 1, "its header is not a recording's (" + e.getMessage() + ")");
        }
    }

    private static void tick(CommandLog log, Map<String, Object> m, String source, int line) {
        if (m.containsKey("failure")) {
            log.failed(ControllerFailure.Kind.valueOf((String) m.get("failure")), (String) m.get("message"));
            return;
        }
        for (Object j : list(m.get("release"))) {
            log.release(((Number) j).intValue());
        }
        for (Object j : list(m.get("claim"))) {
            log.claim(((Number) j).intValue());
        }
        if (m.get("report") instanceof Map<?, ?> r) {
            Object lane = r.get("lane");
            log.report(log.ticks(), new CommandLog.Report(Boolean.TRUE.equals(r.get("overtaking")),
                    Boolean.TRUE.equals(r.get("crossing_junction")), Boolean.TRUE.equals(r.get("waiting_at_junction")),
                    lane == null ? null : Compass.valueOf((String) lane), (String) r.get("stage"),
                    (String) r.get("limited_by"), (String) r.get("steered_by")));
        }
        if (!(m.get("v") instanceof Number) || !(m.get("s") instanceof Number)) {
            throw malformed(source, line, "tick " + log.ticks() + " lacks its speed 'v' or its steering 's'");
        }
        log.command(real(m.get("v")), real(m.get("s")));
        if (m.get("asked") instanceof List<?> asked) {
            log.clamped(real(asked.get(0)), real(asked.get(1)));
        }
    }

    private static Set<Sensor> sensors(Object listed, String source) {
        Set<Sensor> sensors = EnumSet.noneOf(Sensor.class);
        if (!(listed instanceof List<?> names)) {
            throw malformed(source, 1, "'sensors' is not a list");
        }
        for (Object name : names) {
            sensors.add(Sensor.ofWireName(String.valueOf(name)).orElseThrow(() -> malformed(source, 1, "'sensors' names "
                    + name + ", which is not a sensor")));
        }
        return sensors;
    }

    private static List<?> list(Object o) {
        return o instanceof List<?> l ? l : List.of();
    }

    private static double real(Object o) {
        return ((Number) o).doubleValue();
    }

    private static long number(Map<String, Object> m, String name, String source, int line) {
        if (!(m.get(name) instanceof Long v)) {
            throw malformed(source, line, "'" + name + "' is missing or not a whole number");
        }
        return v;
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> object(String line, String source, int number) {
        try {
            if (JsonLine.parse(line) instanceof Map<?, ?> m) {
                return (Map<String, Object>) m;
            }
        } catch (IllegalArgumentException e) {
            throw malformed(source, number, e.getMessage());
        }
        throw malformed(source, number, "it is not a JSON object");
    }

    private static Malformed malformed(String source, int line, String why) {
        return new Malformed(source + ":" + line + " (uncompressed): not a line of a recording: " + why);
    }

    /** A recording that cannot be read, named by file and line. */
    static final class Malformed extends IllegalArgumentException {
        Malformed(String message) {
            super(message);
        }
    }
}
