package io.orchard.protocol.value;

/**
 * The river as a landmark: the nearest point of its bank within the agent's view.
 *
 * @param nearest where the nearest visible point of the river is, relative to the agent
 * @param across  the direction in which the river runs, relative to the agent's heading in
 *                radians (the river can be crossed only at right angles to it, on a bridge)
 */
public record PerceivedRiver(RelativePosition nearest, double across) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public PerceivedRiver {
        Checks.present(nearest, "nearest");
        Checks.finite(across, "across");
    }
}
