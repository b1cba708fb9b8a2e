package io.orchard.agents.language;

/**
 * Why the grammar gave up on a sentence: either a complete answer for the person (a question such
 * as "What should I pick up?", or why the instruction cannot be followed), or a hint of what the
 * agent can do, to follow "I didn't understand ...". Thrown inside the parser only; never escapes
 * {@link InstructionInterpreter}.
 */
final class Refusal extends RuntimeException {

    private static final long serialVersionUID = 1L;

    private final transient String answer;
    private final transient String hint;

    private Refusal(String answer, String hint) {
        super(answer != null ? answer : hint, null, false, false);
        this.answer = answer;
        this.hint = hint;
    }

    /** A refusal with a complete answer. */
    static Refusal answer(String answer) {
        return new Refusal(answer, null);
    }

    /** A refusal to be answered with "I didn't understand ..." and this hint of what the agent can do. */
    static Refusal hint(String hint) {
        return new Refusal(null, hint);
    }

    /** The complete answer, or null when the refusal has a hint instead. */
    String answer() {
        return answer;
    }

    /** What the agent can do, for "I didn't understand ..."; null when the refusal has a complete answer. */
    String hint() {
        return hint;
    }
}
