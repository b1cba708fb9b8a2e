package io.orchard.agents.errand;

import java.util.List;

/**
 * What grounding a reference found in the agent's memory: the objects that fit, none, or several
 * between which the person has to choose.
 */
sealed interface Grounding {

    /** Objects fit; the first is the one chosen (the nearest, unless the reference said otherwise). */
    record Found(List<Known> matches) implements Grounding {
        public Found {
            matches = List.copyOf(matches);
        }

        Known chosen() {
            return matches.get(0);
        }
    }

    /** Nothing the agent knows of fits yet. */
    record Unknown() implements Grounding {}

    /** Several fit and nothing in the words picks one: the person must say which, nearest first. */
    record Ambiguous(List<Known> choices) implements Grounding {
        public Ambiguous {
            choices = List.copyOf(choices);
        }
    }
}
