/**
 * What people ask of an agent: structured goals ({@link io.orchard.agents.goal.Goal}) and the
 * {@link io.orchard.agents.goal.Interpreter} that reads them from a line of text.
 *
 * <p>{@link io.orchard.agents.goal.StructuredGoals} understands a handful of fixed forms
 * ("go to 10,-20", "collect banana", "collect F12", "explore", "stop", "carry on"); a richer
 * interpreter of instructions in English can take its place by implementing the same interface.
 */
package io.orchard.agents.goal;
