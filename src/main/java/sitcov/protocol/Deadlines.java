package sitcov.protocol;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The one thread that enforces every session's per-tick timeout: a session arms its deadline
 * before it writes an observation and disarms it once the command is read, on its own thread, so
 * waiting for an answer needs no thread per tick. A session past its deadline is killed, which
 * ends the blocked read; the session then reports a timeout rather than an exit.
 */
final class Deadlines {
    /** How often deadlines are checked: a timeout fires at most this late. */
    static final long CHECK_MILLIS = 10;

    private static final Set<Session> WATCHED = ConcurrentHashMap.newKeySet();
    private static Thread thread;

    private Deadlines() {
    }

    static synchronized void watch(Session session) {
        WATCHED.add(session);
        if (thread == null) {
            thread = new Thread(Deadlines::loop, "sitcov-controller-deadlines");
            thread.setDaemon(true);
            thread.start();
        }
    }

    static void forget(Session session) {
        WATCHED.remove(session);
    }

    private static void loop() {
        while (true) {
            long now = System.nanoTime();
            for (Session s : WATCHED) {
                s.checkDeadline(now);
            }
            try {
                Thread.sleep(CHECK_MILLIS);
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
