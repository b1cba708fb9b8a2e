package io.orchard.agents.map;

import io.orchard.protocol.value.Point2;

/**
 * Another agent as seen in the latest perception, in world coordinates.
 *
 * @param name     its name
 * @param position where it stood
 * @param heading  its heading in the world (not relative to the perceiver)
 * @param radius   its body's radius
 * @param tick     the tick it was seen in
 */
public record SeenAgent(String name, Point2 position, double heading, double radius, long tick) {}
