/**
 * The world of the paper as the server models it: 2.5D, that is ground shapes on the X/Z plane
 * with heights. Trees and tables are bounding cylinders, the castle is the projection of its walls
 * onto the ground, the river is a band of water across the world, a bridge is two entry points and
 * a width, and fruit are spheres of a fixed radius per kind.
 *
 * <p>{@link io.orchard.server.world.World} is the entry point: it holds the static things with
 * their geometry prepared once, and the fruit still there. It answers the questions the simulation
 * asks every tick: may an agent move along a segment ({@link io.orchard.server.world.MoveResult}),
 * what does it see around it ({@link io.orchard.server.world.NearbyVisitor}), can it grasp a fruit
 * ({@link io.orchard.server.world.Reach}), where is the river, on which bank and on which bridge is
 * a point, in which sector lies the castle and does the castle hide one point from another.
 * {@link io.orchard.server.world.WorldGenerator} makes a world from a seed; scenario files are read
 * and written in {@link io.orchard.server.world.scenario}.
 *
 * <p>The geometry is computed with JTS, but JTS types stay inside this package: public methods take
 * and return the protocol's value records ({@code Point2}, {@code Vec3}, {@code Obstacle}...) and
 * this package's own types. That is also why the geometric operations live here rather than in a
 * subpackage: they share the prepared geometry through package-private accessors.
 *
 * <p>Coordinates follow the protocol: {@code y} is up, the ground is the X/Z plane, north is
 * {@code -z}, east is {@code +x}; a heading of 0 faces north and a positive heading turns left.
 */
package io.orchard.server.world;
