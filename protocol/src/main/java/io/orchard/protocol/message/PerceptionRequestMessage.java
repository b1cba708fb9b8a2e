package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * Asks the server to send the agent its perception in the following simulation cycle: a
 * {@link PerceptionMessage}, a {@link LandmarkPerceptionMessage} and a {@link CastlePerceptionMessage}.
 * With {@code every} above 0 the agent subscribes: it gets them every {@code every} ticks until it
 * sends another request ({@code every} 0 asks once and ends a subscription).
 *
 * @param seq client-chosen sequence number
 * @param agent the agent's name
 * @param every 0 for one perception, N for one every N ticks
 */
public record PerceptionRequestMessage(long seq,
                                       String agent,
                                       int every) implements ClientMessage, AgentMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public PerceptionRequestMessage {
        Checks.nonNegative(seq, "seq");
        Checks.name(agent, "agent");
        Checks.nonNegative(every, "every");
    }
}
