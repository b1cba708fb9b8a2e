package io.orchard.agents.map;

import io.orchard.protocol.value.Point2;

/**
 * What a rejected move taught: the server refused the straight way from {@code from} to {@code to}
 * because something the agent did not know of was in the way.
 *
 * @param from   where the move started
 * @param to     where it should have ended
 * @param what   what was in the way, as the server named it ("tree T17", "the castle", "the river")
 * @param radius the radius of the agent that was refused
 */
public record LearnedBlock(Point2 from, Point2 to, String what, double radius) {}
