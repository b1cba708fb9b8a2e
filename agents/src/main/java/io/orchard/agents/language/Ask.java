package io.orchard.agents.language;

import io.orchard.protocol.value.Nullable;
import java.util.Locale;
import java.util.Objects;

/**
 * A question put to the agent about itself or what it knows: "what do you see?", "where are you?",
 * "how many bananas have you got?", "why did you stop?", "where is the castle?". The agent answers
 * at once, in a short sentence from its own state and memory, and goes on with what it was doing:
 * a question is never a new errand.
 *
 * @param topic what is asked
 * @param about the thing the question names ("where are the bananas?", "do you see the castle?");
 *              null when it names none. {@link Topic#WHERE_IS} always names one.
 */
public record Ask(Topic topic, @Nullable Reference about) implements Goal {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Ask {
        Objects.requireNonNull(topic, "topic");
        if (topic == Topic.WHERE_IS && about == null) {
            throw new IllegalArgumentException("WHERE_IS asks where something is: about must name it, was null");
        }
    }

    /** A question that names nothing, such as "where are you?". */
    public static Ask of(Topic topic) {
        return new Ask(topic, null);
    }

    /** What a question asks. */
    public enum Topic {
        /** What the agent sees now: "what do you see?", "do you see any bananas?". */
        SEE,
        /** Where the agent is, in the world's words: "where are you?". */
        WHERE,
        /** The fruit the agent has collected: "how many fruits have you got?". */
        COLLECTED,
        /** What the agent is doing, and why: "what are you doing?". */
        DOING,
        /** Why the agent stopped, or why its last errand failed: "why did you stop?". */
        WHY,
        /** Where something is, as far as the agent knows: "where are the coconuts?". */
        WHERE_IS,
        /** What the agent can be asked to do: "what can you do?". */
        CAN,
        /** Which way the agent faces: "which way are you facing?". */
        HEADING,
        /** The {@link Rule rules} in force: "what are your rules?". */
        RULES;

        /** The name of this topic in JSON and in the notation: {@code see}, {@code where-is}, ... */
        public String wireName() {
            return name().toLowerCase(Locale.ROOT).replace('_', '-');
        }
    }
}
