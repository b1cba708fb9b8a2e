package io.orchard.agents.language;

/**
 * What reads a person's sentence into a {@link Goal} or an answer: the agents' plug for
 * understanding. {@link InstructionInterpreter}, a deterministic grammar of English, is the one
 * every agent uses unless it overrides {@code AgentController.interpreter()}; a student may supply
 * their own, in any way they like, as long as it gives an {@link Interpretation} for every
 * sentence. Goals made elsewhere can be read from their JSON with {@link GoalJson#read(String)}.
 *
 * <pre>{@code
 * @Override
 * protected Interpreter interpreter() {
 *     InstructionInterpreter english = new InstructionInterpreter();
 *     return sentence -> sentence.equals("dance")
 *             ? new Interpretation.Understood(new Turn(2 * Math.PI), "Dancing.", Optional.empty())
 *             : english.interpret(sentence);
 * }
 * }</pre>
 */
@FunctionalInterface
public interface Interpreter {

    /**
     * What this sentence asks for. Must not throw: a sentence it cannot read gives a
     * {@link Interpretation.NotUnderstood} with an answer for the person.
     *
     * @param sentence what the person typed; may be null, empty or anything else
     */
    Interpretation interpret(String sentence);

    /**
     * What this sentence asks for, said to an agent that spoke of or looked at these things last, so
     * that "that table" or "it" can mean one of them. The default ignores them and reads the sentence
     * alone; {@link InstructionInterpreter} uses them.
     *
     * @param sentence  what the person typed; may be null, empty or anything else
     * @param discourse what the agent spoke about last, most recent first
     */
    default Interpretation interpret(String sentence, Discourse discourse) {
        return interpret(sentence);
    }
}
