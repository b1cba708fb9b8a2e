package io.orchard.cluster.parcel;

import io.orchard.cluster.order.SessionRef;
import io.orchard.server.sim.AgentHandover;

/**
 * An agent with the client that drives it and the label recordings name that client by. A value,
 * sent between nodes.
 *
 * @param agent the agent
 * @param owner the client that drives it
 * @param label the name of that client's first agent
 */
public record OwnedAgent(AgentHandover agent, SessionRef owner, String label) {}
