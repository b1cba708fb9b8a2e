package io.orchard.agents.goal;

import io.orchard.agents.map.WorldMemory;

/**
 * Reads a person's instruction into a {@link Goal}. The agent's memory is at hand for
 * instructions that refer to the world ("the banana on the table").
 */
@FunctionalInterface
public interface Interpreter {

    /**
     * @param text   the instruction as typed
     * @param memory what the agent knows of the world
     * @return the goal it asks for
     * @throws NotUnderstoodException when the text is not an instruction this interpreter knows;
     *                                the message says what it expected
     */
    Goal interpret(String text, WorldMemory memory) throws NotUnderstoodException;
}
