package io.orchard.server.sim;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The order in which the simulation applies what arrived during a tick: client by client, each
 * client's events in the order it sent them. First the server's own tasks and the clients without an
 * agent, in the order they connected; then the clients of agents, in the order of their agents'
 * names rather than of their connections, so that a lockstep game of a seed plays out the same
 * however the clients' threads raced to connect.
 */
final class EventOrder {

    private EventOrder() {}

    /** {@code events} in the order to apply them, given the agents in the world by name. */
    static List<Event> inClientOrder(List<Event> events, Iterable<Agent> agentsByName) {
        Map<Long, List<Event>> bySession = new HashMap<>();
        for (Event event : events) {
            bySession.computeIfAbsent(event.session() == null ? -1L : event.session().id(),
                    id -> new ArrayList<>(2)).add(event);
        }
        if (bySession.size() < 2) {
            return events;
        }
        List<Event> named = new ArrayList<>(events.size());
        for (Agent agent : agentsByName) {
            List<Event> own = bySession.remove(agent.owner.id());
            if (own != null) {
                named.addAll(own);
            }
        }
        List<Long> unnamed = new ArrayList<>(bySession.keySet());
        unnamed.sort(null);
        List<Event> ordered = new ArrayList<>(events.size());
        for (Long id : unnamed) {
            ordered.addAll(bySession.get(id));
        }
        ordered.addAll(named);
        return ordered;
    }
}
