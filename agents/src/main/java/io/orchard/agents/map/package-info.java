/**
 * The world as an agent remembers it: map building from perceptions.
 *
 * <p>{@link io.orchard.agents.map.WorldMemory} takes each perception (trees, tables and agents
 * relative to the perceiver, fruit absolute, the river, the bridges and the castle's compass
 * sector) and keeps what it learnt in world coordinates: the obstacles with the circle that blocks
 * walking, the fruit seen and the fruit known to be gone, the bridges, a model of the river band
 * ({@link io.orchard.agents.map.RiverMap}), an estimate of where the castle stands
 * ({@link io.orchard.agents.map.CastleEstimate}), which parts of the world have been looked at
 * ({@link io.orchard.agents.map.Coverage}), where the agent has stood
 * ({@link io.orchard.agents.map.Trail}) and what rejected moves taught it.
 * {@link io.orchard.agents.map.Bearings} converts between relative and world positions.
 *
 * <p>Nothing here acts or talks to the server; the types are not thread-safe and belong to the
 * thread of the agent's controller.
 */
package io.orchard.agents.map;
