package io.orchard.agents.language;

import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * What an agent spoke about or looked at last, most recent first, for the words that point at it:
 * "that table", "those tomatoes", "it". The person cannot point in the world, so a demonstrative
 * means the last thing of its kind the agent named ("I'm at the table T3."), turned to or saw;
 * with none, the interpreter asks which one is meant. The agent's errands keep it
 * ({@code Errands.discourse()}); an interpreter reads a sentence in it with
 * {@link Interpreter#interpret(String, Discourse)}.
 *
 * @param mentions the things spoken of, most recent first, each once
 */
public record Discourse(List<Mention> mentions) {

    /** Nothing spoken of yet. */
    public static final Discourse NONE = new Discourse(List.of());

    /**
     * One thing spoken of.
     *
     * @param kind its kind: a fruit's, a tree, a table, a bridge, or an agent
     * @param id   the world's id ("T3", "F12", "B1"), or the agent's name
     */
    public record Mention(Reference.Kind kind, String id) {

        /** Checks the components; a bad value is refused with an exception that names it. */
        public Mention {
            Objects.requireNonNull(kind, "kind");
            Objects.requireNonNull(id, "id");
            if (!kind.hasIds() && kind != Reference.Kind.AGENT) {
                throw new IllegalArgumentException("only fruit, trees, tables, bridges and agents are mentioned by "
                        + "id, not a " + kind.wireName());
            }
        }

        /** This thing as a reference: "the table T3", "Roadrunner". */
        public Reference reference() {
            return kind == Reference.Kind.AGENT ? Reference.agent(id) : Reference.thing(kind, id);
        }
    }

    /** Checks the components and keeps its own copy of the list. */
    public Discourse {
        mentions = List.copyOf(mentions);
    }

    /** The last thing spoken of that a word of this kind can mean ("fruit" any fruit); empty when none. */
    public Optional<Mention> last(Reference.Kind kind) {
        return mentions.stream().filter(m -> m.kind() == kind || (kind == Reference.Kind.FRUIT && m.kind().isFruit()))
                .findFirst();
    }

    /** The last thing spoken of; empty when none. */
    public Optional<Mention> last() {
        return mentions.stream().findFirst();
    }
}
