/**
 * Understanding instructions: a person directs an agent in simple English, and the agent, still
 * autonomous, pursues what it understood.
 *
 * <p>{@link io.orchard.agents.language.InstructionInterpreter#interpret(String)} turns a sentence
 * into an {@link io.orchard.agents.language.Interpretation}: either a typed
 * {@link io.orchard.agents.language.Goal} ({@link io.orchard.agents.language.GoTo},
 * {@link io.orchard.agents.language.Collect}, {@link io.orchard.agents.language.Follow}, ...) with
 * the agent's one-line restatement, or a helpful answer that names the words it did not know.
 * Goals refer to the world through {@link io.orchard.agents.language.Reference references} —
 * descriptions such as "the nearest banana on a table" — that the agent's controller grounds in
 * what the agent remembers of the world. {@link io.orchard.agents.language.GoalJson} writes goals
 * as JSON, as {@code ./orchard parse "SENTENCE"} prints them.
 *
 * <p>The public types are immutable values and a thread-safe interpreter; the tokenizer, the
 * vocabulary, the speller and the grammar are package-private. The accepted grammar, the
 * vocabulary and the forms of goals are documented in {@code docs/instructions.md}.
 */
package io.orchard.agents.language;
