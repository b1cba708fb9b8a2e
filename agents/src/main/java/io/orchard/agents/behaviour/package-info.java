/**
 * Behaviours an agent composes: each is usable on its own, acts through a {@link
 * io.orchard.agents.behaviour.Motor} and reads a {@link io.orchard.agents.map.WorldMemory}.
 *
 * <ul>
 *   <li>{@link io.orchard.agents.behaviour.PathPlanner}: paths over the remembered map, A* on a
 *       half-unit grid around trunks and tables, over the river only by a bridge, then
 *       straightened;
 *   <li>{@link io.orchard.agents.behaviour.Navigator}: goes to a point along a planned path, steps
 *       around other agents, and learns from rejected moves what the plan did not know;
 *   <li>{@link io.orchard.agents.behaviour.Harvester}: approaches a fruit, faces it, brings the
 *       gripper into reach and grasps, and handles a failed grasp;
 *   <li>{@link io.orchard.agents.behaviour.Explorer}: heads for what the memory has not seen;
 *   <li>{@link io.orchard.agents.behaviour.Wanderer}: walks about at random;
 *   <li>{@link io.orchard.agents.behaviour.Steering}: purely reactive steering from the current
 *       perception alone, for agents that keep no map;
 *   <li>{@link io.orchard.agents.behaviour.Forager}: the default autonomy that puts them together;
 *   <li>{@link io.orchard.agents.behaviour.Headway}: whether the agent is getting anywhere, and
 *       {@link io.orchard.agents.behaviour.Commitment}: the plan it keeps to once it is not.
 * </ul>
 *
 * <p>Instructed goals are pursued with the same behaviours by
 * {@link io.orchard.agents.errand.Errands}.
 *
 * <p>Behaviours are called on the controller's thread, once per tick; none is thread-safe.
 */
package io.orchard.agents.behaviour;
