package io.orchard.server.world;

import io.orchard.protocol.value.Checks;

/**
 * The answer to "can this agent grasp that fruit from where it stands?", with the reason in words
 * when it cannot ("fruit F3 is 2.4 units away, reach is 1.2").
 *
 * @param reachable whether the grasp succeeds
 * @param reason    why not, or "fruit F3 is within reach"
 */
public record ReachResult(boolean reachable, String reason) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public ReachResult {
        Checks.present(reason, "reason");
    }
}
