package io.orchard.agents.language;

import java.util.List;

/** The words of the interpreter's answers, in one place. */
final class Answers {

    static final String CAN_DO = "I can go to places, collect fruit, explore, follow, turn, stop";
    static final String CAN_GO = "I can go to the castle, the river, a bridge, a tree, a table or another agent, "
            + "or go north, south, east or west";
    static final String CAN_COLLECT = "I can pick up tomatoes, bananas and coconuts, on the ground, on tables "
            + "and in trees";
    static final String CAN_CROSS = "I can cross the river, a bridge or the forest";
    static final String CAN_TURN = "I can turn left, right or around, by a number of degrees, or to face north, "
            + "south, east or west";
    static final String CAN_LOOK = "I can look for fruit, trees, tables, the castle, the river, a bridge or an "
            + "agent, look at them, or look around";
    static final String CAN_EXPLORE = "I can explore the forest, an area such as the other side of the river, "
            + "or anywhere";
    static final String CAN_WAIT = "I can wait here, or wait for a number of seconds or minutes";
    static final String CAN_STOP = "I can stop, or stop and wait here";

    static final String EMPTY = "Tell me what to do, for example 'go to the castle' or 'pick up the nearest "
            + "banana'; " + CAN_DO + ".";
    static final String YES = "Yes? Tell me what to do, for example 'go to the castle' or 'pick up the nearest "
            + "banana'.";
    static final String TOO_LONG = "That is too long for me; please give me one short instruction at a time, "
            + "for example 'go to the castle, then pick up a tomato'.";
    static final String NEGATION = "I can be told not to go somewhere ('don't go near the river') or not to take "
            + "some fruit ('don't eat the tomatoes'); for anything else tell me what to do rather than what not to do, "
            + "'stop' to make me stop, or 'carry on' to let me go on by myself.";
    static final String WHERE = "Where should I go? Say, for example, 'go to the castle', 'cross the bridge' or "
            + "'go north'.";
    static final String WHAT_PICK = "What should I pick up? Say, for example, 'pick up the nearest banana'.";
    static final String WHAT_LOOK = "What should I look for? Say, for example, 'look for coconuts' or 'look "
            + "around'.";
    static final String WHAT_LOOK_AT = "What should I look at? Say, for example, 'look at the castle'.";
    static final String WALK_RANGE = "I can walk more than 0 and up to " + (int) RelativeMove.MAX_DISTANCE
            + " metres at a time; say, for example, 'go north 20 metres'.";
    static final String DISTANCE_WHICH_WAY = "Which way should I walk that far: north, south, east, west, forward,"
            + " back, left or right?";
    static final String WHICH_WAY = "Which way should I turn: left, right or around?";
    static final String TURN_RANGE = "I can turn by up to 360 degrees at a time; say, for example, 'turn 90 "
            + "degrees to the left'.";
    static final String WHICH_FACE = "Which way should I face? Say, for example, 'face north' or 'face the "
            + "castle'.";
    static final String WHERE_THERE = "I don't know where 'there' is; tell me a place, for example 'go to the "
            + "castle'.";
    static final String WHERE_HERE = "I cannot see where you are; tell me a place, for example 'go to the castle',"
            + " or say 'come back'.";
    static final String ONE_PLACE = "I can go to only one place at a time; say, for example, 'go to the nearest "
            + "tree'.";
    static final String ZERO = "Collecting none is doing nothing; say how many, for example 'collect three "
            + "bananas', or 'collect all bananas'.";
    static final String TOO_MANY = "That is more fruit than the world holds; say 'all' to collect every one, "
            + "for example 'collect all bananas'.";
    static final String WHOLE = "I can collect only whole fruit; say how many, for example 'collect two bananas'.";
    static final String NEGATIVE = "I can't do something a negative number of times; say how many, for example "
            + "'collect two bananas'.";
    static final String CAN_RULE = "I can keep rules until you lift them: where not to go ('don't go near the "
            + "river', 'stay on this side of the river'), which fruit to leave or to take ('leave the coconuts', 'only "
            + "bananas from now on'), and what to do when I see something ('when you see a banana, take it')";
    static final String CAN_WATCH = "I can act when I see something, for example 'when you see a banana, take it' "
            + "or 'if you see Roadrunner, follow him'";
    static final String WHAT_WATCH = "What should I watch for? Say, for example, 'when you see a banana, take it'.";
    static final String CONDITIONS = "I can act only when I see something, as in 'when you see a banana, take it' "
            + "or 'if you find a coconut, bring it to me', and only by doing something (not by setting a rule or "
            + "asking); I can't wait for anything else to happen.";
    static final String LASTING = "I can keep from now on only rules: where not to go ('don't go near the river'), "
            + "which fruit to leave or to take ('leave the coconuts', 'only bananas from now on'), and what to do "
            + "when I see something ('when you see a banana, take it'); anything else, tell me to do now.";
    static final String LIFT_WHAT = "I can lift a rule about where I may go or what I may take, for example 'you "
            + "can go near the river again', 'you may take coconuts again', or all of them: 'forget the rules'.";
    static final String RULES_HOW = "Ask me 'what are your rules?', lift them with 'forget the rules', or give me "
            + "one, for example 'don't go near the river'.";
    static final String ONLY_WHAT = "Which fruit should I take from now on? Say, for example, 'only bananas from "
            + "now on' or 'only collect coconuts'.";
    static final String LEAVE_WHAT = "What should I leave alone? I can leave fruit, for example 'leave the "
            + "coconuts'.";
    static final String AVOID_WHAT = "What should I keep away from? Say, for example, 'stay away from the river' "
            + "or 'avoid the forest'.";
    static final String ORDINAL_HOW = "I can count things by how near they are or from the left or the right, up "
            + "to the " + Restatement.ordinal(Reference.MAX_ORDINAL) + "; say, for example, 'the second nearest tree' or "
            + "'the third table from the left'.";
    static final String DEMONSTRATIVE = "I don't know which one you mean by '%s'; name it another way, for example "
            + "'the nearest table' or 'the table by the castle'.";
    static final String GENERIC_FAILURE = "Sorry, I could not make sense of that; " + CAN_DO + ".";

    private Answers() {
    }

    /** The answer to a sentence in another language, in English. */
    static String otherLanguage(String language) {
        return "I understand only English" + (language.startsWith("another") ? "" : ", and that looks like "
                + language) + "; say, for example, 'pick up the banana' or 'go to the castle'.";
    }

    static String whom(List<String> agents) {
        return "Whom should I follow? I know " + list(agents, "and") + ".";
    }

    static String followMe(List<String> agents) {
        return "I cannot see you in the world; tell me whom to follow: " + list(agents, "or") + ".";
    }

    static String canFollow(List<String> agents) {
        return "I can follow other agents, such as " + list(agents, "or");
    }

    static String followNotAgent(String what, List<String> agents) {
        return "I can only follow other agents, such as " + list(agents, "or") + ", not " + what + ".";
    }

    static String collectNotFruit(String what) {
        return "I can only pick up fruit (tomatoes, bananas and coconuts), not " + what + ".";
    }

    static String crossNot(String what) {
        return "I can cross the river, a bridge or the forest, not " + what + ".";
    }

    static String whatToDoWith(String words, Reference reference) {
        String first = reference == null ? "explore " : reference.isFruit() ? "pick up "
                : reference.kind() == Reference.Kind.AGENT ? "follow " : "go to ";
        String second = reference == null || reference.isFruit() || reference.kind() == Reference.Kind.AGENT
                ? "' or 'go to " + words : "' or 'look for " + words;
        return "What should I do with '" + words + "'? Say, for example, '" + first + words + second + "'.";
    }

    static String whatWhenSeen(String what) {
        return "What should I do when I see " + what + "? Say, for example, 'when you see a banana, take it'.";
    }

    static String pronoun(String word, String question) {
        return "I don't know what '" + word + "' is yet. " + question;
    }

    static String notUnderstood(String sentence, List<String> unknown, String hint) {
        String because = unknown.isEmpty() ? "" : " (I don't know " + list(unknown.stream()
                .map(word -> "'" + word + "'").toList(), "or") + ")";
        return "I didn't understand '" + sentence + "'" + because + "; " + hint + ".";
    }

    /** "a", "a and b", "a, b and c". */
    static String list(List<String> items, String conjunction) {
        if (items.size() <= 1) {
            return String.join("", items);
        }
        return String.join(", ", items.subList(0, items.size() - 1)) + " " + conjunction + " "
                + items.get(items.size() - 1);
    }
}
