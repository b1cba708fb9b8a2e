package io.orchard.server.sim;

/**
 * Where a walker's segment first meets another agent, as one part of a world answers another
 * ({@link PartialSimulation}): the single server's rule takes the nearest, and on a tie the agent of
 * the earlier name.
 *
 * @param distance how far along the segment
 * @param agent    the agent met
 */
public record FirstContact(double distance, String agent) {

    /** Whether this contact comes before {@code other} (null: none), by the single server's rule. */
    public boolean before(FirstContact other) {
        return other == null || distance < other.distance()
                || distance == other.distance() && agent.compareTo(other.agent()) < 0;
    }
}
