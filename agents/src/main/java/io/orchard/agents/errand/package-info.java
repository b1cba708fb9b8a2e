/**
 * Carrying out what people ask: {@link io.orchard.agents.errand.Errands} takes the
 * {@link io.orchard.agents.language.Goal goals} that the
 * {@link io.orchard.agents.language.InstructionInterpreter} reads from English and pursues them
 * with the agent's {@link io.orchard.agents.behaviour behaviours}.
 *
 * <p>Inside, one small class per concern: the grounder finds in the agent's
 * {@link io.orchard.agents.map.WorldMemory memory} what a reference means (by kind, name, size,
 * distance and place); a question asks which of several landmarks is meant and reads the answer;
 * a reach check refuses what the body cannot do at all (fruit in a tree for a mouth at the ground);
 * and one pursuit per kind of goal (going to a thing or into an area, crossing, collecting,
 * turning, searching, exploring, following, walking, holding still) does the walking. Only
 * {@code Errands} is public: an agent author calls it through
 * {@link io.orchard.agents.AgentController#pursueInstruction()}, or replaces it by overriding
 * {@code onGoal}.
 *
 * <p>Everything here runs on the controller's thread, once per tick; nothing is thread-safe.
 */
package io.orchard.agents.errand;
