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
 * hands out records it made once and allocates nothing per object. Each thing comes with its index,
 * which stays the same for the world's life: a tree's or table's in {@link World#obstacles()}, a
 * fruit's in {@link World#allFruitStates()}; a visitor that keeps only indices need not read the
 * record at all (reading it is a trip to memory per thing). The order of the calls is fixed for a
 * given world and query but otherwise unspecified. Both methods do nothing unless overridden.
 */
public interface NearbyVisitor {

    /** A tree or table, item {@code index} of the world's obstacles, centred on (x, z), {@code distance} units away on the ground. */
    default void obstacle(int index, Obstacle obstacle, double x, double z, double distance) {}

    /** A fruit, item {@code index} of all the world's fruit, centred on (x, z) on the ground, {@code distance} units away. */
    default void fruit(int index, FruitState fruit, double x, double z, double distance) {}
}
