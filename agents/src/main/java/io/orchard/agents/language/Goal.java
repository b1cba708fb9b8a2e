package io.orchard.agents.language;

/**
 * What a person asked an agent to do, as a typed value: the result of
 * {@link InstructionInterpreter#interpret(String) understanding} an instruction such as "pick up
 * the nearest banana on a table". A goal says what is wanted, never how: the agent's controller
 * grounds its {@link Reference references} in what the agent remembers of the world and pursues
 * it on its own, avoiding obstacles and choosing its gripper as usual. When a goal is reached
 * (or cannot be), the agent returns to its autonomous behaviour unless the goal said otherwise
 * ({@link Stop}, {@link Wait}).
 *
 * <p>The goals, in the world's words:
 * <ul>
 *   <li>going: {@link GoTo} a place, {@link Cross} the river or a bridge, {@link Head} in a compass
 *       direction, {@link RelativeMove} forward, back, left or right, {@link ComeBack};</li>
 *   <li>collecting: {@link Collect} fruit;</li>
 *   <li>looking: {@link Turn} by an angle, {@link Face} a compass direction, {@link LookAt} an
 *       object, {@link LookFor} something, {@link Explore} an area;</li>
 *   <li>other agents: {@link Follow};</li>
 *   <li>autonomy: {@link Stop}, {@link Wait}, {@link CarryOn};</li>
 *   <li>several goals one after the other: {@link Sequence};</li>
 *   <li>a question to answer at once, without dropping what the agent does: {@link Ask};</li>
 *   <li>standing {@link Rule rules} that hold until {@link Lift lifted}: places to {@link Avoid}, fruit
 *       to {@link Leave} or to take {@link Only}, and conditions to act on ({@link WhenSee}).</li>
 * </ul>
 *
 * <p>Every goal is an immutable record whose constructor validates it; goals compare by value.
 * Without pattern matching for switch (Java 17), dispatch with {@code instanceof}:
 * <pre>{@code
 * if (goal instanceof Collect collect) {
 *     pursueCollect(collect.what(), collect.count());
 * } else if (goal instanceof GoTo goTo) {
 *     ...
 * }
 * }</pre>
 */
public sealed interface Goal
        permits GoTo, Cross, Head, RelativeMove, ComeBack, Collect, Turn, Face, LookAt, LookFor, Explore, Follow,
        Stop, Wait, CarryOn, Sequence, Ask, Rule, Lift {

    /**
     * The agent's one-line English restatement of this goal, for it to say back to the person, e.g.
     * "Going to pick up the nearest banana that lies on a table." or "Going to the castle, then
     * picking up a tomato."
     */
    default String restatement() {
        return Restatement.of(this);
    }

    /**
     * The agent's restatement of this goal in a language it speaks: in German "Ich hebe die nächste
     * Banane auf, die auf einem Tisch liegt."
     */
    default String restatement(Language language) {
        return language == Language.GERMAN ? GermanRestatement.of(this) : Restatement.of(this);
    }

    /**
     * This goal in a compact text notation, one line, as the test corpus and logs write goals, e.g.
     * {@code collect(nearest banana on(table))} or {@code go-to(castle); collect(tomato)}. The
     * notation is described in {@code docs/instructions.md}; equal goals have equal notations.
     */
    default String notation() {
        return Notation.of(this);
    }
}
