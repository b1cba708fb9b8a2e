/**
 * The paper's five agents, each with its body, its model (in this package's {@code models}
 * resources) and a control architecture of its own, so that the testbed can compare them:
 *
 * <table>
 *   <caption>The zoo</caption>
 *   <tr><th>agent</th><th>body</th><th>architecture</th></tr>
 *   <tr><td>{@link io.orchard.agents.zoo.Dwarf}</td><td>anthropomorphic; collects with its hands</td>
 *       <td>subsumption layers</td></tr>
 *   <tr><td>{@link io.orchard.agents.zoo.Robot}</td><td>two-legged robot with claws</td>
 *       <td>map building with a planner</td></tr>
 *   <tr><td>{@link io.orchard.agents.zoo.Bunny}</td><td>four-legged; mouth; only what lies on the ground</td>
 *       <td>purely reactive</td></tr>
 *   <tr><td>{@link io.orchard.agents.zoo.Guppy}</td><td>anthropomorphic, the paper's Figure 5 model</td>
 *       <td>a goal stack</td></tr>
 *   <tr><td>{@link io.orchard.agents.zoo.Roadrunner}</td><td>two-legged animat; neck of four joints, beak of two parts</td>
 *       <td>behaviour-based arbiter with utility scores</td></tr>
 * </table>
 *
 * <p>Each explores and collects on its own until the game ends, follows instructions in English
 * ("walk to the big tree by the river", "pick up the coconut on the table", "stop", "carry on")
 * and returns to its autonomy when an instruction is done. Each gives an instruction its place in
 * its own architecture (a layer, a behaviour, a goal on the stack, a pause of the plan or of the
 * rules); the controller's {@link io.orchard.agents.errand.Errands} carry it out.
 * {@link io.orchard.agents.zoo.Species} makes them by name.
 */
package io.orchard.agents.zoo;
