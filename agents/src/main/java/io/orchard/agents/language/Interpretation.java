package io.orchard.agents.language;

import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;

/**
 * What {@link InstructionInterpreter#interpret(String)} made of a sentence: either it
 * {@link Understood understood} it as a {@link Goal}, or it did {@link NotUnderstood not}, and then
 * it has an answer for the person. Either way the sentence may have been addressed to one agent
 * by name ("Guppy, stop"); an agent should act on an interpretation only when
 * {@link #isFor(String) it is for it}.
 *
 * <pre>{@code
 * Interpretation heard = interpreter.interpret(line);
 * if (heard.isFor(myName)) {
 *     if (heard instanceof Interpretation.Understood understood) {
 *         say(understood.restatement());
 *         pursue(understood.goal());
 *     } else if (heard instanceof Interpretation.NotUnderstood notUnderstood) {
 *         say(notUnderstood.answer());
 *     }
 * }
 * }</pre>
 */
public sealed interface Interpretation {

    /** The agent the sentence was addressed to, as the person wrote its name; empty when it named none. */
    Optional<String> addressee();

    /** The language the sentence was read in, and its answer is in. */
    Language language();

    /**
     * Whether an agent with this name should act on the sentence: when it named no one, or named
     * this agent (ignoring case).
     */
    default boolean isFor(String agentName) {
        return addressee().map(name -> name.toLowerCase(Locale.ROOT).equals(
                agentName.toLowerCase(Locale.ROOT))).orElse(true);
    }

    /**
     * The sentence was understood.
     *
     * @param goal        what the person wants done
     * @param restatement the agent's one-line English restatement of the goal, to say back
     * @param addressee   the agent the sentence was addressed to, if it named one
     * @param language    the language the sentence was read in, and the restatement is in
     */
    record Understood(Goal goal, String restatement, Optional<String> addressee, Language language)
            implements Interpretation {

        /** Checks the components; a bad value is refused with an exception that names it. */
        public Understood {
            Objects.requireNonNull(goal, "goal");
            Objects.requireNonNull(restatement, "restatement");
            Objects.requireNonNull(addressee, "addressee");
            Objects.requireNonNull(language, "language");
        }

        /** A sentence understood in English. */
        public Understood(Goal goal, String restatement, Optional<String> addressee) {
            this(goal, restatement, addressee, Language.ENGLISH);
        }
    }

    /**
     * The sentence was not understood, or asks for something the agent cannot do, or leaves out
     * something the agent needs to know ("pick it up" with nothing said before).
     *
     * @param answer       a helpful answer to say back: what went wrong (naming unknown words) or a
     *                     question, and what the agent can do
     * @param unknownWords the words of the sentence the agent does not know, as written, in order;
     *                     empty when every word was known
     * @param addressee    the agent the sentence was addressed to, if it named one
     * @param language     the language the sentence was read in, and the answer is in
     */
    record NotUnderstood(String answer, List<String> unknownWords, Optional<String> addressee, Language language)
            implements Interpretation {

        /**
         * Checks the components and keeps its own copy of the lists; a bad value is refused with an exception
         * that names it.
         */
        public NotUnderstood {
            Objects.requireNonNull(answer, "answer");
            unknownWords = List.copyOf(unknownWords);
            Objects.requireNonNull(addressee, "addressee");
            Objects.requireNonNull(language, "language");
        }

        /** A sentence not understood, answered in English. */
        public NotUnderstood(String answer, List<String> unknownWords, Optional<String> addressee) {
            this(answer, unknownWords, addressee, Language.ENGLISH);
        }
    }
}
