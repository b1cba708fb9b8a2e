package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * The fruit of the world. Each kind is a sphere of fixed radius and is worth a fixed number of
 * points to the agent that collects it; bigger fruit is worth more.
 */
public enum FruitKind {
    /** A small red tomato: radius 0.15, 1 point. */
    TOMATO("tomato", 0.15, 1),

    /** A yellow banana: radius 0.25, 2 points. */
    BANANA("banana", 0.25, 2),

    /** A brown coconut: radius 0.35, 3 points. */
    COCONUT("coconut", 0.35, 3);

    private final String wireName;
    private final double radius;
    private final int points;

    FruitKind(String wireName, double radius, int points) {
        this.wireName = wireName;
        this.radius = radius;
        this.points = points;
    }

    /** The radius of this kind's sphere in world units. */
    public double radius() {
        return radius;
    }

    /** The points an agent scores for collecting one. */
    public int points() {
        return points;
    }

    /** The name of this value on the wire. */
    @JsonValue
    public String wireName() {
        return wireName;
    }
}
