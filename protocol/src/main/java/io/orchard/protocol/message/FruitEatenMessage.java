package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.FruitKind;

/**
 * Sent to every agent when any agent has collected a fruit.
 *
 * @param tick the tick it happened in
 * @param fruit the fruit's id
 * @param kind its kind
 * @param agent who collected it
 */
public record FruitEatenMessage(long tick,
                                String fruit,
                                FruitKind kind,
                                String agent) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public FruitEatenMessage {
        Checks.nonNegative(tick, "tick");
        Checks.id(fruit, "fruit");
        Checks.present(kind, "kind");
        Checks.name(agent, "agent");
    }
}
