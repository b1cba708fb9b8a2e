package io.orchard.protocol.value;

/**
 * Another agent in an agent's perception.
 *
 * @param name    the other agent's name
 * @param at      where it is relative to the perceiving agent
 * @param heading its heading relative to the perceiver's, in radians (0: facing the same way)
 * @param radius  its body radius
 */
public record PerceivedAgent(String name, RelativePosition at, double heading, double radius) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public PerceivedAgent {
        Checks.name(name, "name");
        Checks.present(at, "at");
        Checks.finite(heading, "heading");
        Checks.positive(radius, "radius");
    }
}
