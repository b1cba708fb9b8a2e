package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Reference;
import java.util.List;

/**
 * Looking for something until it is in sight, without collecting it: fruit must be seen in the
 * latest perception, other things known. The agent explores meanwhile, and stops when it sees one.
 */
final class Searching implements Pursuit {

    private final Kit kit;
    private final Reference what;
    private String outcome = "";

    Searching(Kit kit, Reference what) {
        this.kit = kit;
        this.what = what;
    }

    @Override
    public Status step() {
        List<Known> fits = kit.grounder.select(what, kit.grounder.fitting(what));
        for (Known known : fits) {
            if (known.fruit() == null || known.fruit().seenTick() >= kit.memory.tick()) {
                kit.standStill();
                kit.mention(known);
                outcome = kit.speech.iSee(known, kit.here());
                return Status.DONE;
            }
        }
        if (kit.explorer.step(kit.navigator) == Status.DONE) {
            outcome = kit.speech.lookedEverywhere(what);
            return Status.FAILED;
        }
        return Status.RUNNING;
    }

    @Override
    public String outcome() {
        return outcome;
    }
}
