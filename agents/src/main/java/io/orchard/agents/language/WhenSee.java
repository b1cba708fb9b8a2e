package io.orchard.agents.language;

import java.util.Objects;

/**
 * A condition, until lifted: "when you see a banana, take it", "whenever you see a tomato, grab
 * it", "if you see the castle, go there". Each time the agent, on its own, sees something that fits
 * {@link #what()} that it has not acted on before, it pursues {@link #then()} for that very thing,
 * and goes back to its own behaviour afterwards. In {@code then}, the references equal to
 * {@code what} stand for the thing seen ("it", "there").
 *
 * @param what what to watch for
 * @param then what to do each time: an action or a sequence of actions, not a rule, a question or
 *             "carry on"
 */
public record WhenSee(Reference what, Goal then) implements Rule {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public WhenSee {
        Objects.requireNonNull(what, "what");
        Objects.requireNonNull(then, "then");
        if (what.kind() == Reference.Kind.PLACE || what.kind() == Reference.Kind.START) {
            throw new IllegalArgumentException("a condition watches for something to see, not a "
                    + what.kind().wireName());
        }
        for (Goal step : then instanceof Sequence sequence ? sequence.steps() : java.util.List.of(then)) {
            if (step instanceof Rule || step instanceof Lift || step instanceof Ask || step instanceof CarryOn) {
                throw new IllegalArgumentException("what to do when something is seen must be an action, not "
                        + step.notation());
            }
        }
    }
}
