package io.orchard.agents.language;

/**
 * A standing rule: a goal that is not done and over, but holds from the moment it is given until
 * it is {@link Lift lifted}, and that the agent's own foraging, planning and exploring obey as
 * well as every errand: a place not to go ({@link Avoid}), fruit not to take ({@link Leave}) or
 * the only fruit to take ({@link Only}), and a condition to act on whenever it comes true
 * ({@link WhenSee}). A rule given while the agent is on an errand leaves the errand going, now
 * under the rule; "what are your rules?" ({@link Ask.Topic#RULES}) lists those in force.
 */
public sealed interface Rule extends Goal permits Avoid, Leave, Only, WhenSee {

    /**
     * The rule as it holds, in the agent's words, for "what are your rules?": "I don't go near the
     * river", "I leave the coconuts alone", "whenever I see a banana, I pick it up".
     */
    default String statement() {
        return Restatement.statement(this);
    }

    /**
     * The rule as the reason the agent gives when it will not do something: "your rule not to go near
     * the river", "your rule to leave the coconuts alone".
     */
    default String reason() {
        return Restatement.reason(this);
    }

    /** {@link #statement()} in a language the agents speak: in German "ich gehe nicht in die Nähe des Flusses". */
    default String statement(Language language) {
        return language == Language.GERMAN ? GermanRestatement.statement(this) : statement();
    }

    /** {@link #reason()} in a language the agents speak: in German "deine Regel: ich lasse die Kokosnüsse liegen". */
    default String reason(Language language) {
        return language == Language.GERMAN ? GermanRestatement.reason(this) : reason();
    }
}
