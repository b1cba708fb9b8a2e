package io.orchard.server.world;

import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;

/**
 * Receives what lies within range of a point, from
 * {@link World#visitWithin(double, double, double, NearbyVisitor)}: the broad phase of perception.
 * The world gives every tree, table and fruit whose centre is within range, with its ground
 * distance from the point and its centre (x, z) on the ground, read from the world's own arrays so
 * that rejecting it costs no trip to the record; the caller applies the field of view and whatever else it perceives by.
 *
 * <p>A visitor rather than a list because perception runs for every agent on every tick: the world
 * hands out records it made once and allocates nothing per object. The order of the calls is fixed
 * for a given world and query but otherwise unspecified. Both methods do nothing unless overridden.
 */
public interface NearbyVisitor {

    /** A tree or table centred on (x, z), {@code distance} units away on the ground. */
    default void obstacle(Obstacle obstacle, double x, double z, double distance) {}

    /** A fruit centred on (x, z) on the ground, {@code distance} units away. */
    default void fruit(FruitState fruit, double x, double z, double distance) {}
}
