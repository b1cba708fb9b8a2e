package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Reference;

/**
 * Looking for something the agent needs and does not know of yet: it says so once ("I don't know
 * of a coconut on a table yet; I'll look for one.") and explores, until memory has it or there is
 * nothing left to see.
 */
final class Looking {

    private final Kit kit;
    private final Reference wanted;
    private boolean said;

    Looking(Kit kit, Reference wanted) {
        this.kit = kit;
        // "the nearest tree" when none is known is any tree: "I don't know of a tree yet"
        boolean superlative = wanted.size() == Reference.Size.LARGEST || wanted.size() == Reference.Size.SMALLEST;
        this.wanted = wanted.withDistance(null).withSize(superlative ? null : wanted.size());
    }

    /** One tick of exploring: RUNNING, or FAILED once everything reachable has been seen. */
    Status step() {
        if (!said) {
            said = true;
            kit.motor.say(announcement());
        }
        return kit.explorer.step(kit.navigator) == Status.DONE ? Status.FAILED : Status.RUNNING;
    }

    /** What the agent says as it sets out to look. */
    String announcement() {
        Reference.Kind kind = wanted.kind();
        if (kind == Reference.Kind.AGENT && wanted.name() != null) {
            return kit.speech.cantSee(wanted.name());
        }
        if (kind == Reference.Kind.CASTLE || kind == Reference.Kind.RIVER || kind == Reference.Kind.FOREST) {
            return kit.speech.dontKnowWhere(wanted);
        }
        return kit.speech.dontKnowOf(wanted);
    }

    /** What to say when the search found nothing. */
    String failure() {
        return kit.speech.lookedEverywhere(wanted);
    }
}
