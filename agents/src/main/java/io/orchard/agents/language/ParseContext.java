package io.orchard.agents.language;

import java.util.HashSet;
import java.util.Set;

/**
 * What the grammar knows of one sentence as it reads it: whom it is addressed to, what it last
 * referred to (for "it", "them", "one", "there"), which fruit it last collected, which unknown
 * words it took as agents' names, and what to answer if the clause it is reading fails.
 */
final class ParseContext {

    /** The positions of unknown words taken as agents' names. */
    final Set<Integer> namesTaken = new HashSet<>();

    /** The agent the sentence is addressed to, or null. */
    String addressee;

    /** Whether the sentence says its rule lasts: "from now on". */
    boolean lasting;

    /** Whether the sentence says "again": with {@link #permit}, it lifts a rule. */
    boolean again;

    /** Whether the sentence gives leave: "you can", "you may". */
    boolean permit;

    /** What the agent spoke about or looked at last, for "that table" and "it". */
    Discourse discourse = Discourse.NONE;

    /** What the sentence last referred to, or null. */
    Reference antecedent;

    /** The fruit the sentence last asked to collect, or null. */
    Reference lastCollected;

    /** The answers in the language of the sentence. */
    Answers answers = Answers.ENGLISH;

    /** What the agent can do, to answer "I didn't understand ..." in the clause being read. */
    String hint = Answers.ENGLISH.CAN_DO;

    /** What to ask when a pronoun in the clause being read refers to nothing. */
    String question = Answers.ENGLISH.WHAT_PICK;
}
