package io.orchard.agents.map;

import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.Objects;

/**
 * A fruit this agent took, and where: what "go back to where you found the coconut" goes back to.
 *
 * @param fruitId the fruit's id
 * @param kind    tomato, banana or coconut
 * @param fruit   the fruit as the agent knew it before it took it; null when it had not seen it
 * @param stood   where the agent stood when it took it, a place it could stand
 */
public record Find(String fruitId, FruitKind kind, @Nullable KnownFruit fruit, Point2 stood) {

    /** Checks the components; a missing one is refused with an exception that names it. */
    public Find {
        Objects.requireNonNull(fruitId, "fruitId");
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(stood, "stood");
    }
}
