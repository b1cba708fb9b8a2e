package io.orchard.server.sim;

import io.orchard.protocol.message.EndTurnMessage;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Whose turn a lockstep game waits for, and who missed theirs. An agent's client ends its setup
 * (registration, joints, sensors, perception request) with an {@code EndTurn} before the game
 * starts, and every tick's turn with an {@code EndTurn} for that tick. A client that misses
 * {@link #LATE_AFTER} turns in a row is late: ticks no longer wait for it, until it ends a turn in
 * time again. Owned by the simulation's thread; clients are known by their session numbers.
 */
final class Turns {

    /** Turns missed in a row after which ticks no longer wait for a client. */
    static final int LATE_AFTER = 3;

    private final Set<Long> setUp = new HashSet<>();
    private final Map<Long, Integer> missedInARow = new HashMap<>();
    private final Set<Long> late = new HashSet<>();
    /** The agents' clients when the tick began: the ones whose turns it has. */
    private List<Long> expected = List.of();

    /** The client ended its setup turn. */
    void setupEnded(long session) {
        setUp.add(session);
    }

    /** Those of {@code clients} that have not ended their setup turn, in the order given. */
    List<Long> notSetUp(Collection<Long> clients) {
        return clients.stream().filter(id -> !setUp.contains(id)).toList();
    }

    /** The game started without these clients' setup turns. */
    void setupMissed(Collection<Long> clients) {
        clients.forEach(this::missed);
    }

    /** A tick begins with these agents' clients. */
    void began(List<Long> agentClients) {
        expected = agentClients;
    }

    /**
     * The clients this tick waits for: every agent's client that is not late, or all of them when
     * all are late (there is then no one whom waiting would hold up).
     */
    List<Long> waitFor() {
        List<Long> inTime = expected.stream().filter(id -> !late.contains(id)).toList();
        return inTime.isEmpty() ? expected : inTime;
    }

    /**
     * The tick {@code tick} ends with {@code events}: who among its clients did not end their turn
     * in it, and how (a client that left is not counted). Ordered as the clients were given.
     */
    Map<Long, MissedTurn.Kind> ended(long tick, List<Event> events, Collection<Long> stillConnected) {
        Set<Long> ended = new HashSet<>();
        for (Event event : events) {
            if (event instanceof Event.Received received && received.message() instanceof EndTurnMessage end
                    && end.tick() >= tick) {
                ended.add(received.session().id());
            }
        }
        return ended(ended, stillConnected);
    }

    /**
     * The tick ends with these clients' turns ended: who among its clients did not end theirs, and
     * how (a client that left is not counted). Ordered as the clients were given.
     */
    Map<Long, MissedTurn.Kind> ended(Set<Long> ended, Collection<Long> stillConnected) {
        Map<Long, MissedTurn.Kind> missed = new LinkedHashMap<>();
        for (Long id : new ArrayList<>(expected)) {
            if (!stillConnected.contains(id)) {
                forget(id);
            } else if (ended.contains(id)) {
                missedInARow.remove(id);
                late.remove(id);
            } else {
                missed.put(id, late.contains(id) ? MissedTurn.Kind.LATE : MissedTurn.Kind.DEADLINE);
                missed(id);
            }
        }
        return missed;
    }

    /** A client left. */
    void forget(long session) {
        setUp.remove(session);
        missedInARow.remove(session);
        late.remove(session);
    }

    private void missed(long session) {
        if (missedInARow.merge(session, 1, Integer::sum) >= LATE_AFTER) {
            late.add(session);
        }
    }
}
