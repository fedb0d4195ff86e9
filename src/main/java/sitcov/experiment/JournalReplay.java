package sitcov.experiment;

import java.util.List;

/**
 * Judges a resumed session's maps from the journal, in order, checking that the session asks for the
 * maps the journal holds (same candidates, same decisions); past the journal's last map, judges with
 * {@code then}.
 */
final class JournalReplay implements SessionJudge {
    private final List<Journal.Entry> entries;
    private final int replication;
    private final String driver;
    private final DriverClock clock;
    private final SessionJudge then;

    private JournalReplay(List<Journal.Entry> entries, DriverClock clock, SessionJudge then) {
        this.entries = List.copyOf(entries);
        this.replication = entries.get(0).run().replication();
        this.driver = entries.get(0).run().driver();
        this.clock = clock;
        this.then = then;
    }

    /** Judges a session whose journal holds {@code entries} for it: from them, then with {@code fresh}. */
    static SessionJudge over(List<Journal.Entry> entries, FreshJudge fresh, DriverClock clock) {
        return entries.isEmpty() ? fresh : new JournalReplay(entries, clock, fresh);
    }

    @Override
    public Judgement judge(Request r) {
        int index = r.index();
        if (index >= entries.size()) {
            return then.judge(r);
        }
        Journal.Entry e = entries.get(index);
        MapRun run = e.run();
        if (!run.map().equals(r.id()) || run.candidate() != r.candidate() || run.cell() != r.cell()) {
            throw new IllegalStateException("the journal does not match this run: map " + index + " of driver " + driver
                    + " in replication " + replication + " is " + run.map().text() + " (candidate " + run.candidate()
                    + ") in the journal but " + r.id().text() + " (candidate " + r.candidate() + ") now");
        }
        clock.replayed(e.driverNanos(), index == entries.size() - 1);
        return new Judgement(run, true, e.mapNanos(), e.driverNanos(), java.util.Map.of());
    }
}
