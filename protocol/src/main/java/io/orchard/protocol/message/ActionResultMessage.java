package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Vec3;

/**
 * The result of an action (move, rotation, joint, animation, registration of a joint or time
 * sensor, perception request, unregistration, game command): accepted, blocked or rejected with the reason.
 *
 * @param seq the action's sequence number
 * @param agent the agent that acted; absent for a game command
 * @param action the action's message type, for example {@code Move}
 * @param outcome accepted, blocked or rejected
 * @param reason why it was blocked or rejected ("path crosses tree T17")
 * @param position for moves: where the agent will stand when the move ends
 * @param duration for moves: how long the move takes in simulated seconds; otherwise 0
 */
public record ActionResultMessage(long seq,
                                  @Nullable String agent,
                                  String action,
                                  Outcome outcome,
                                  @Nullable String reason,
                                  @Nullable Vec3 position,
                                  double duration) implements ServerMessage, Reply {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public ActionResultMessage {
        Checks.nonNegative(seq, "seq");
        if (agent != null) {
            Checks.name(agent, "agent");
        }
        Checks.text(action, "action");
        Checks.present(outcome, "outcome");
        Checks.optionalText(reason, "reason");
        Checks.nonNegative(duration, "duration");
    }
}
