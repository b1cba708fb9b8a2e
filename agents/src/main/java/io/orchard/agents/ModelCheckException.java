package io.orchard.agents;

import java.util.List;

/**
 * An agent's model lacks what registration needs: a Transform named after the agent, or the
 * nodes of the joints and time sensors the agent registers. The message lists every problem.
 */
public final class ModelCheckException extends IllegalArgumentException {

    private static final long serialVersionUID = 1L;

    private final transient List<String> problems;

    /**
     * The model {@code source} cannot be registered, for the {@code problems} found in it.
     *
     * @param source   the model's name
     * @param problems each problem in words
     */
    public ModelCheckException(String source, List<String> problems) {
        super("model " + source + " cannot be registered: " + String.join("; ", problems));
        this.problems = List.copyOf(problems);
    }

    /** Each problem found, in words ("no joint LeftKnee: the model has no node DEF 'LeftKnee'"). */
    public List<String> problems() {
        return problems;
    }
}
