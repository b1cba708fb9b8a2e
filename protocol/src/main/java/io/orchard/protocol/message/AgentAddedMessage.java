package io.orchard.protocol.message;

import io.orchard.protocol.value.AgentState;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.ModelSpec;

/**
 * An agent entered the world, with its model for viewers to load.
 *
 * @param tick the tick it happened in
 * @param agent the agent
 */
public record AgentAddedMessage(long tick,
                                AgentState agent) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public AgentAddedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.present(agent, "agent");
    }

    /**
     * This message as a client of protocol version 1 is sent it: the same when its model is one
     * version 1 knows; otherwise without the version 2 parts of the model ({@code fit}), or without
     * the model, which such a viewer shows as a placeholder, when its format is of version 2.
     */
    public AgentAddedMessage forVersion1() {
        ModelSpec model = agent.model();
        if (model == null || model.forVersion1() == model) {
            return this;
        }
        return new AgentAddedMessage(tick, new AgentState(agent.name(), agent.body(), agent.position(),
                agent.heading(), model.forVersion1(), agent.joints(), agent.timeSensors()));
    }
}
