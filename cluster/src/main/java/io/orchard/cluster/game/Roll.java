package io.orchard.cluster.game;

import io.orchard.cluster.parcel.ParcelId;
import io.orchard.server.sim.AgentHandover;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * The agents of a split game as its tick knows them, by name: the client that drives each, the
 * parcel that owns it, and the agent as the parcels last said it was. The game's thread's alone.
 */
final class Roll {

    private final Map<String, Link> owners = new TreeMap<>();
    private final Map<String, ParcelId> where = new HashMap<>();
    private final Map<String, AgentHandover> states = new TreeMap<>();

    /** An agent entered the game, owned by {@code parcel}. */
    void add(AgentHandover agent, Link owner, ParcelId parcel) {
        owners.put(agent.name(), owner);
        where.put(agent.name(), parcel);
        states.put(agent.name(), agent);
    }

    /** An agent left the game. */
    void remove(String name) {
        owners.remove(name);
        where.remove(name);
        states.remove(name);
    }

    /** Whether an agent of that name is in the game. */
    boolean has(String name) {
        return owners.containsKey(name);
    }

    /** The client that drives the agent, or null. */
    Link owner(String name) {
        return owners.get(name);
    }

    /** The parcel that owns the agent, or null. */
    ParcelId parcel(String name) {
        return where.get(name);
    }

    /** The agent as last said, or null. */
    AgentHandover state(String name) {
        return states.get(name);
    }

    /** The agent is now as said; nothing for an agent no longer in the game. */
    void update(AgentHandover agent) {
        if (states.containsKey(agent.name())) {
            states.put(agent.name(), agent);
        }
    }

    /** The agent walked into another parcel. */
    void moveTo(String name, ParcelId parcel) {
        where.put(name, parcel);
    }

    /** Every agent as last said, by name. */
    Collection<AgentHandover> states() {
        return states.values();
    }

    /** The parcels that own agents. */
    Set<ParcelId> parcels() {
        return new HashSet<>(where.values());
    }

    /** The names of the agents the client {@code session} drives, in order. */
    List<String> namesOf(long session) {
        List<String> names = new ArrayList<>();
        owners.forEach((name, owner) -> {
            if (owner.id() == session) {
                names.add(name);
            }
        });
        return names;
    }

    /** Each client that drives agents, by number, with the name of its first agent: its rank in a tick. */
    Map<Long, String> ranks() {
        Map<Long, String> rank = new HashMap<>();
        owners.forEach((name, owner) -> rank.putIfAbsent(owner.id(), name));
        return rank;
    }

    /** How many agents are in the game. */
    int size() {
        return owners.size();
    }
}
