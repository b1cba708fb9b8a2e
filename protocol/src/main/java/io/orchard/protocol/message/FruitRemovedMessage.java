package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;

/**
 * A fruit is gone from the world: remove it from the scene.
 *
 * @param tick the tick it happened in
 * @param fruit the fruit's id
 * @param agent who collected it
 */
public record FruitRemovedMessage(long tick,
                                  String fruit,
                                  String agent) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public FruitRemovedMessage {
        Checks.nonNegative(tick, "tick");
        Checks.id(fruit, "fruit");
        Checks.name(agent, "agent");
    }
}
