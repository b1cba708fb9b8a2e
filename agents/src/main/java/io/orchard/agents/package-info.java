/**
 * What an agent's author touches: {@link io.orchard.agents.AgentController}, the base every Java
 * agent extends, with {@link io.orchard.agents.AgentBody} (what the agent registers),
 * {@link io.orchard.agents.AgentModel} (its visual model, read from its resources and checked),
 * {@link io.orchard.agents.Perception} (one tick's view) and
 * {@link io.orchard.agents.AgentStats} (what it did).
 *
 * <h2>A new agent</h2>
 * Override {@code body()} and nothing else, and the agent explores and collects fruit on its own
 * (the default {@code decide} is a {@link io.orchard.agents.behaviour.Forager}) and follows
 * instructions in English ("pick up the coconut on the table", "cross the bridge", "stop"), which
 * its {@link io.orchard.agents.errand.Errands} ground, answer and pursue. To give it behaviour of
 * your own, override {@code decide} too, and call {@code pursueInstruction()} first so that it
 * stays instructable. This one walks about until it sees a fruit its hands reach, walks up to it,
 * faces it and grasps it:
 *
 * <pre>{@code
 * public final class Pippin extends AgentController {
 *
 *     public Pippin() {
 *         super("Pippin");
 *     }
 *
 *     @Override
 *     protected AgentBody body() {
 *         return AgentBody.builder().radius(0.4).speed(6).gripper("hands", 0.6, 0, 1.6).build();
 *     }
 *
 *     @Override
 *     protected void decide(Perception seen) {
 *         if (pursueInstruction()) {               // told what to do: that comes first
 *             return;
 *         }
 *         Point2 here = seen.ground();
 *         Gripper hands = bodyInForce().gripper();
 *         Optional<PerceivedFruit> fruit = seen.nearestFruit(f -> f.position().y() < hands.maxHeight() - 0.01);
 *         if (fruit.isEmpty()) {                    // nothing in view: walk on, somewhere new
 *             if (!walking()) {
 *                 walkTo(Bearings.ahead(here, heading() + random().nextGaussian(), 10));
 *             }
 *             return;
 *         }
 *         Point2 at = fruit.get().position().onGround();
 *         double reach = bodyInForce().radius() + hands.reach() + fruit.get().radius();
 *         if (here.distance(at) < reach - 0.1) {   // within reach: face it and grasp
 *             face(at);
 *             grasp(fruit.get().id());
 *         } else if (!walking()) {          // walk up to it
 *             walkTo(Bearings.ahead(here, Bearings.headingTowards(here, at), here.distance(at) - reach + 0.3));
 *         }
 *     }
 *
 *     public static void main(String[] args) throws Exception {
 *         System.out.println(new Pippin().run("localhost", 7557).ranking());
 *     }
 * }
 * }</pre>
 *
 * <p>It has no eyes for trees: a move through one is refused, and it simply tries another way
 * next tick. The {@link io.orchard.agents.behaviour behaviours} do better: paths planned over the
 * {@link io.orchard.agents.map.WorldMemory memory} that the controller keeps, a harvester that
 * finds a spot in reach. The model: put {@code Pippin.x3d} next to the class and add
 * {@code .model("Pippin.x3d")} to the body; its root must be {@code DEF Pippin Transform}.
 *
 * <p>The paper's five agents are in {@link io.orchard.agents.zoo}; {@code ./orchard agent} runs
 * one of them ({@link io.orchard.agents.cli.AgentMain}).
 *
 * <p>Inside, the controller is assembled from package-private parts with one job each: the
 * connection ({@code Session}, kept under the server's rate by a {@code Throttle}), registering
 * ({@code Registration}), the clock and the agent's turns in it ({@code Turns}, with a
 * {@code PerceptionSchedule}), what the agent is and knows ({@code Situation}), its actions
 * ({@code ControllerMotor}, which follows its moves and grasps and plays the walk animation), its
 * default behaviours ({@code Behaviours}), its counts ({@code Tally}), and the loop that takes the
 * server's messages one at a time and calls the hooks ({@code GameLoop}).
 */
package io.orchard.agents;
