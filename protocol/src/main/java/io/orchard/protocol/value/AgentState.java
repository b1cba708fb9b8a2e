package io.orchard.protocol.value;

import java.util.List;

/**
 * An agent as viewers need it to show it: its body, where it is, its model and the names of the
 * joints and time sensors its controller registered.
 *
 * @param name        the agent's name; its model's root Transform carries the same name
 * @param body        the body in force
 * @param position    where it stands
 * @param heading     its heading in radians (see {@link Rotation})
 * @param model       its visual model; absent when it sent none (viewers show a placeholder)
 * @param joints      registered joints
 * @param timeSensors registered time sensors (animations)
 */
public record AgentState(String name, Body body, Vec3 position, double heading, @Nullable ModelSpec model,
                         List<String> joints, List<String> timeSensors) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public AgentState {
        Checks.name(name, "name");
        Checks.present(body, "body");
        Checks.present(position, "position");
        Checks.finite(heading, "heading");
        joints = Checks.list(joints, "joints");
        timeSensors = Checks.list(timeSensors, "timeSensors");
    }
}
