package io.orchard.protocol.value;

/**
 * One agent's standing in the game. Scores survive an agent's disconnect.
 *
 * @param agent  the agent's name
 * @param points points scored (see {@link FruitKind#points()})
 * @param fruit  number of fruit collected
 */
public record Score(String agent, int points, int fruit) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Score {
        Checks.name(agent, "agent");
        Checks.nonNegative(points, "points");
        Checks.nonNegative(fruit, "fruit");
    }
}
