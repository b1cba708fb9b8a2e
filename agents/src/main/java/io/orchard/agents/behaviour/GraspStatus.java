package io.orchard.agents.behaviour;

import io.orchard.protocol.value.Nullable;

/**
 * The agent's latest grasp as its controller knows it.
 *
 * @param fruit    the fruit grasped at
 * @param tick     the tick the request was sent in
 * @param answered whether the server's result came
 * @param success  whether the fruit is the agent's (false until answered)
 * @param reason   why it failed; null otherwise
 */
public record GraspStatus(String fruit, long tick, boolean answered, boolean success, @Nullable String reason) {}
