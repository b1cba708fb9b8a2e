package io.orchard.agents.language;

import java.util.List;

/**
 * The words of the interpreter's answers, in one place, in each language the agents speak: the
 * answers to a sentence not understood are given in the language of the sentence.
 */
final class Answers {

    /** The answers in English. */
    static final Answers ENGLISH = new Answers(false);
    /** The answers in German. */
    static final Answers GERMAN = new Answers(true);

    final Language language;
    final String CAN_DO;
    final String CAN_GO;
    final String CAN_COLLECT;
    final String CAN_CROSS;
    final String CAN_TURN;
    final String CAN_LOOK;
    final String CAN_EXPLORE;
    final String CAN_WAIT;
    final String CAN_STOP;
    final String EMPTY;
    final String YES;
    final String TOO_LONG;
    final String NEGATION;
    final String WHERE;
    final String WHAT_PICK;
    final String WHAT_LOOK;
    final String WHAT_LOOK_AT;
    final String WALK_RANGE;
    final String DISTANCE_WHICH_WAY;
    final String WHICH_WAY;
    final String TURN_RANGE;
    final String WHICH_FACE;
    final String WHERE_THERE;
    final String WHERE_HERE;
    final String ONE_PLACE;
    final String ZERO;
    final String TOO_MANY;
    final String WHOLE;
    final String NEGATIVE;
    final String CAN_RULE;
    final String CAN_WATCH;
    final String WHAT_WATCH;
    final String CONDITIONS;
    final String LASTING;
    final String LIFT_WHAT;
    final String RULES_HOW;
    final String ONLY_WHAT;
    final String LEAVE_WHAT;
    final String AVOID_WHAT;
    final String ORDINAL_HOW;
    final String DEMONSTRATIVE;
    final String GENERIC_FAILURE;
    final String WAIT_RANGE;

    private Answers(boolean de) {
        language = de ? Language.GERMAN : Language.ENGLISH;
        CAN_DO = de ? "ich kann zu Orten gehen, Früchte sammeln, erkunden, folgen, mich drehen und anhalten"
                : "I can go to places, collect fruit, explore, follow, turn, stop";
        CAN_GO = de ? "ich kann zum Schloss, zum Fluss, zu einer Brücke, einem Baum, einem Tisch oder einem anderen "
                + "Agenten gehen, oder nach Norden, Süden, Osten oder Westen"
                : "I can go to the castle, the river, a bridge, a tree, a table or another agent, or go north, south, "
                + "east or west";
        CAN_COLLECT = de ? "ich kann Tomaten, Bananen und Kokosnüsse aufheben, vom Boden, von Tischen und aus Bäumen"
                : "I can pick up tomatoes, bananas and coconuts, on the ground, on tables and in trees";
        CAN_CROSS = de ? "ich kann den Fluss, eine Brücke oder den Wald überqueren"
                : "I can cross the river, a bridge or the forest";
        CAN_TURN = de ? "ich kann mich nach links, nach rechts oder um mich drehen, um eine Zahl von Grad, oder nach "
                + "Norden, Süden, Osten oder Westen"
                : "I can turn left, right or around, by a number of degrees, or to face north, south, east or west";
        CAN_LOOK = de ? "ich kann nach Früchten, Bäumen, Tischen, dem Schloss, dem Fluss, einer Brücke oder einem "
                + "Agenten suchen, sie anschauen, oder mich umsehen"
                : "I can look for fruit, trees, tables, the castle, the river, a bridge or an agent, look at them, or "
                + "look around";
        CAN_EXPLORE = de ? "ich kann den Wald erkunden, eine Gegend wie die andere Seite des Flusses, oder überall"
                : "I can explore the forest, an area such as the other side of the river, or anywhere";
        CAN_WAIT = de ? "ich kann hier warten, oder eine Zahl von Sekunden oder Minuten"
                : "I can wait here, or wait for a number of seconds or minutes";
        CAN_STOP = de ? "ich kann anhalten, oder anhalten und hier warten" : "I can stop, or stop and wait here";
        EMPTY = de ? "Sag mir, was ich tun soll, zum Beispiel 'geh zum Schloss' oder 'nimm die nächste Banane'; "
                + CAN_DO + "." : "Tell me what to do, for example 'go to the castle' or 'pick up the nearest banana'; "
                + CAN_DO + ".";
        YES = de ? "Ja? Sag mir, was ich tun soll, zum Beispiel 'geh zum Schloss' oder 'nimm die nächste Banane'."
                : "Yes? Tell me what to do, for example 'go to the castle' or 'pick up the nearest banana'.";
        TOO_LONG = de ? "Das ist mir zu lang; gib mir bitte eine kurze Anweisung nach der anderen, zum Beispiel 'geh "
                + "zum Schloss, dann nimm eine Tomate'." : "That is too long for me; please give me one short instruction "
                + "at a time, for example 'go to the castle, then pick up a tomato'.";
        NEGATION = de ? "Man kann mir sagen, wohin ich nicht gehen soll ('geh nicht in die Nähe des Flusses') oder "
                + "welche Früchte ich nicht nehmen soll ('iss keine Tomaten'); sonst sag mir lieber, was ich tun soll, "
                + "'halt', damit ich anhalte, oder 'mach weiter', damit ich allein weitermache."
                : "I can be told not to go somewhere ('don't go near the river') or not to take some fruit ('don't eat "
                + "the tomatoes'); for anything else tell me what to do rather than what not to do, 'stop' to make me "
                + "stop, or 'carry on' to let me go on by myself.";
        WHERE = de ? "Wohin soll ich gehen? Sag zum Beispiel 'geh zum Schloss', 'überquere die Brücke' oder 'geh nach "
                + "Norden'." : "Where should I go? Say, for example, 'go to the castle', 'cross the bridge' or 'go "
                + "north'.";
        WHAT_PICK = de ? "Was soll ich aufheben? Sag zum Beispiel 'nimm die nächste Banane'."
                : "What should I pick up? Say, for example, 'pick up the nearest banana'.";
        WHAT_LOOK = de ? "Wonach soll ich suchen? Sag zum Beispiel 'such nach Kokosnüssen' oder 'sieh dich um'."
                : "What should I look for? Say, for example, 'look for coconuts' or 'look around'.";
        WHAT_LOOK_AT = de ? "Was soll ich anschauen? Sag zum Beispiel 'schau das Schloss an'."
                : "What should I look at? Say, for example, 'look at the castle'.";
        WALK_RANGE = de ? "Ich kann auf einmal mehr als 0 und bis zu " + (int) RelativeMove.MAX_DISTANCE + " Meter "
                + "gehen; sag zum Beispiel 'geh 20 Meter nach Norden'." : "I can walk more than 0 and up to "
                + (int) RelativeMove.MAX_DISTANCE + " metres at a time; say, for example, 'go north 20 metres'.";
        DISTANCE_WHICH_WAY = de ? "In welche Richtung soll ich so weit gehen: nach Norden, Süden, Osten, Westen, "
                + "vorwärts, zurück, nach links oder nach rechts?" : "Which way should I walk that far: north, south, "
                + "east, west, forward, back, left or right?";
        WHICH_WAY = de ? "Wohin soll ich mich drehen: nach links, nach rechts oder um?"
                : "Which way should I turn: left, right or around?";
        TURN_RANGE = de ? "Ich kann mich auf einmal um höchstens 360 Grad drehen; sag zum Beispiel 'dreh dich um 90 Grad "
                + "nach links'." : "I can turn by up to 360 degrees at a time; say, for example, 'turn 90 degrees to the "
                + "left'.";
        WHICH_FACE = de ? "Wohin soll ich schauen? Sag zum Beispiel 'schau nach Norden' oder 'schau das Schloss an'."
                : "Which way should I face? Say, for example, 'face north' or 'face the castle'.";
        WHERE_THERE = de ? "Ich weiß nicht, wo 'dort' ist; nenn mir einen Ort, zum Beispiel 'geh zum Schloss'."
                : "I don't know where 'there' is; tell me a place, for example 'go to the castle'.";
        WHERE_HERE = de ? "Ich kann nicht sehen, wo du bist; nenn mir einen Ort, zum Beispiel 'geh zum Schloss', oder "
                + "sag 'komm zurück'." : "I cannot see where you are; tell me a place, for example 'go to the castle', "
                + "or say 'come back'.";
        ONE_PLACE = de ? "Ich kann nur zu einem Ort auf einmal gehen; sag zum Beispiel 'geh zum nächsten Baum'."
                : "I can go to only one place at a time; say, for example, 'go to the nearest tree'.";
        ZERO = de ? "Keine zu sammeln heißt nichts zu tun; sag, wie viele, zum Beispiel 'sammle drei Bananen' oder "
                + "'sammle alle Bananen'." : "Collecting none is doing nothing; say how many, for example 'collect "
                + "three bananas', or 'collect all bananas'.";
        TOO_MANY = de ? "So viele Früchte gibt es in der Welt nicht; sag 'alle', um jede zu sammeln, zum Beispiel "
                + "'sammle alle Bananen'." : "That is more fruit than the world holds; say 'all' to collect every one, "
                + "for example 'collect all bananas'.";
        WHOLE = de ? "Ich kann nur ganze Früchte sammeln; sag, wie viele, zum Beispiel 'sammle zwei Bananen'."
                : "I can collect only whole fruit; say how many, for example 'collect two bananas'.";
        NEGATIVE = de ? "Ich kann nichts eine negative Zahl von Malen tun; sag, wie viele, zum Beispiel 'sammle zwei "
                + "Bananen'." : "I can't do something a negative number of times; say how many, for example 'collect "
                + "two bananas'.";
        CAN_RULE = de ? "ich kann mich an Regeln halten, bis du sie aufhebst: wohin ich nicht gehen soll ('geh nicht in "
                + "die Nähe des Flusses', 'bleib auf dieser Seite des Flusses'), welche Früchte ich liegen lassen oder "
                + "nehmen soll ('lass die Kokosnüsse liegen', 'ab jetzt nur noch Bananen'), und was ich tun soll, wenn "
                + "ich etwas sehe ('wenn du eine Banane siehst, nimm sie')"
                : "I can keep rules until you lift them: where not to go ('don't go near the river', 'stay on this side "
                + "of the river'), which fruit to leave or to take ('leave the coconuts', 'only bananas from now on'), "
                + "and what to do when I see something ('when you see a banana, take it')";
        CAN_WATCH = de ? "ich kann etwas tun, wenn ich etwas sehe, zum Beispiel 'wenn du eine Banane siehst, nimm sie' "
                + "oder 'wenn du Roadrunner siehst, folge ihm'" : "I can act when I see something, for example 'when "
                + "you see a banana, take it' or 'if you see Roadrunner, follow him'";
        WHAT_WATCH = de ? "Worauf soll ich achten? Sag zum Beispiel 'wenn du eine Banane siehst, nimm sie'."
                : "What should I watch for? Say, for example, 'when you see a banana, take it'.";
        CONDITIONS = de ? "Ich kann nur etwas tun, wenn ich etwas sehe, wie in 'wenn du eine Banane siehst, nimm sie', "
                + "und nur, indem ich etwas tue (keine Regel und keine Frage); auf anderes kann ich nicht warten."
                : "I can act only when I see something, as in 'when you see a banana, take it' or 'if you find a "
                + "coconut, bring it to me', and only by doing something (not by setting a rule or asking); I can't "
                + "wait for anything else to happen.";
        LASTING = de ? "Ab jetzt kann ich mich nur an Regeln halten: wohin ich nicht gehen soll ('geh nicht in die "
                + "Nähe des Flusses'), welche Früchte ich liegen lassen oder nehmen soll ('lass die Kokosnüsse liegen', "
                + "'ab jetzt nur noch Bananen'), und was ich tun soll, wenn ich etwas sehe ('wenn du eine Banane "
                + "siehst, nimm sie'); alles andere sag mir für jetzt."
                : "I can keep from now on only rules: where not to go ('don't go near the river'), which fruit to leave "
                + "or to take ('leave the coconuts', 'only bananas from now on'), and what to do when I see something "
                + "('when you see a banana, take it'); anything else, tell me to do now.";
        LIFT_WHAT = de ? "Ich kann eine Regel darüber aufheben, wohin ich gehen oder was ich nehmen darf, zum Beispiel "
                + "'du darfst wieder in die Nähe des Flusses gehen', 'du darfst wieder Kokosnüsse nehmen', oder alle: "
                + "'vergiss die Regeln'." : "I can lift a rule about where I may go or what I may take, for example 'you "
                + "can go near the river again', 'you may take coconuts again', or all of them: 'forget the rules'.";
        RULES_HOW = de ? "Frag mich 'was sind deine Regeln?', heb sie mit 'vergiss die Regeln' auf, oder gib mir eine, "
                + "zum Beispiel 'geh nicht in die Nähe des Flusses'." : "Ask me 'what are your rules?', lift them with "
                + "'forget the rules', or give me one, for example 'don't go near the river'.";
        ONLY_WHAT = de ? "Welche Früchte soll ich ab jetzt nehmen? Sag zum Beispiel 'ab jetzt nur noch Bananen' oder "
                + "'sammle nur Kokosnüsse'." : "Which fruit should I take from now on? Say, for example, 'only bananas "
                + "from now on' or 'only collect coconuts'.";
        LEAVE_WHAT = de ? "Was soll ich liegen lassen? Ich kann Früchte liegen lassen, zum Beispiel 'lass die "
                + "Kokosnüsse liegen'." : "What should I leave alone? I can leave fruit, for example 'leave the "
                + "coconuts'.";
        AVOID_WHAT = de ? "Wovon soll ich mich fernhalten? Sag zum Beispiel 'halte dich vom Fluss fern' oder 'meide den "
                + "Wald'." : "What should I keep away from? Say, for example, 'stay away from the river' or 'avoid the "
                + "forest'.";
        ORDINAL_HOW = de ? "Ich kann Dinge danach zählen, wie nah sie sind, oder von links oder von rechts, bis zum "
                + "zwanzigsten; sag zum Beispiel 'der zweitnächste Baum' oder 'der dritte Tisch von links'."
                : "I can count things by how near they are or from the left or the right, up to the "
                + Restatement.ordinal(Reference.MAX_ORDINAL) + "; say, for example, 'the second nearest tree' or 'the "
                + "third table from the left'.";
        DEMONSTRATIVE = de ? "Ich weiß nicht, welchen du mit '%s' meinst; nenn ihn anders, zum Beispiel 'der nächste "
                + "Tisch' oder 'der Tisch beim Schloss'." : "I don't know which one you mean by '%s'; name it another "
                + "way, for example 'the nearest table' or 'the table by the castle'.";
        GENERIC_FAILURE = de ? "Entschuldigung, daraus werde ich nicht schlau; " + CAN_DO + "."
                : "Sorry, I could not make sense of that; " + CAN_DO + ".";
        WAIT_RANGE = de ? "Ich kann bis zu einem Tag warten; " + CAN_WAIT + "." : "I can wait up to a day; " + CAN_WAIT
                + ".";
    }

    /** The answers in this language. */
    static Answers of(Language language) {
        return language == Language.GERMAN ? GERMAN : ENGLISH;
    }

    private boolean german() {
        return language == Language.GERMAN;
    }

    /** One object of a reference in words, as the answers name it (the accusative in German, or the dative). */
    String noun(Reference reference, boolean dative) {
        return german() ? GermanRestatement.noun(reference, dative ? GermanRestatement.Case.DAT
                : GermanRestatement.Case.ACC) : Restatement.noun(reference);
    }

    /** "the world", "the ground": what cannot be picked up. */
    String world(boolean ground) {
        return german() ? (ground ? "den Boden" : "die Welt") : ground ? "the ground" : "the world";
    }

    /** The answer to a sentence in another language than those understood, in this language. */
    String otherLanguage(String language, List<Language> understood) {
        if (german()) {
            String names = understood.size() > 1 ? "Deutsch und Englisch" : "Deutsch";
            String like = switch (language) {
                case "French" -> "Französisch";
                case "Spanish" -> "Spanisch";
                case "Italian" -> "Italienisch";
                case "Dutch" -> "Niederländisch";
                case "German" -> "Deutsch";
                case "English" -> "Englisch";
                default -> "";
            };
            return "Ich verstehe nur " + names + (like.isEmpty() ? "" : ", und das sieht nach " + like + " aus")
                    + "; sag zum Beispiel 'nimm die Banane' oder 'geh zum Schloss'.";
        }
        String names = understood.size() > 1 ? "English and German" : "English";
        return "I understand only " + names + (language.startsWith("another") ? "" : ", and that looks like "
                + language) + "; say, for example, 'pick up the banana' or 'go to the castle'.";
    }

    String whom(List<String> agents) {
        return german() ? "Wem soll ich folgen? Ich kenne " + list(agents, "und") + "."
                : "Whom should I follow? I know " + list(agents, "and") + ".";
    }

    String followMe(List<String> agents) {
        return german() ? "Ich kann dich in der Welt nicht sehen; sag mir, wem ich folgen soll: " + list(agents, "oder")
                + "." : "I cannot see you in the world; tell me whom to follow: " + list(agents, "or") + ".";
    }

    String canFollow(List<String> agents) {
        return german() ? "ich kann anderen Agenten folgen, etwa " + list(agents, "oder")
                : "I can follow other agents, such as " + list(agents, "or");
    }

    String followNotAgent(String what, List<String> agents) {
        return german() ? "Ich kann nur anderen Agenten folgen, etwa " + list(agents, "oder") + ", nicht " + what + "."
                : "I can only follow other agents, such as " + list(agents, "or") + ", not " + what + ".";
    }

    String collectNotFruit(String what) {
        return german() ? "Ich kann nur Früchte aufheben (Tomaten, Bananen und Kokosnüsse), nicht " + what + "."
                : "I can only pick up fruit (tomatoes, bananas and coconuts), not " + what + ".";
    }

    String crossNot(String what) {
        return german() ? "Ich kann den Fluss, eine Brücke oder den Wald überqueren, nicht " + what + "."
                : "I can cross the river, a bridge or the forest, not " + what + ".";
    }

    String whatToDoWith(String words, Reference reference) {
        if (german()) {
            String example = reference == null ? "erkunde " + words : reference.isFruit() ? "nimm " + words
                    : reference.kind() == Reference.Kind.AGENT ? "folge " + words : "geh zu " + words;
            return "Was soll ich mit '" + words + "' tun? Sag zum Beispiel '" + example + "'.";
        }
        String first = reference == null ? "explore " : reference.isFruit() ? "pick up "
                : reference.kind() == Reference.Kind.AGENT ? "follow " : "go to ";
        String second = reference == null || reference.isFruit() || reference.kind() == Reference.Kind.AGENT
                ? "' or 'go to " + words : "' or 'look for " + words;
        return "What should I do with '" + words + "'? Say, for example, '" + first + words + second + "'.";
    }

    String whatWhenSeen(String what) {
        return german() ? "Was soll ich tun, wenn ich " + what + " sehe? Sag zum Beispiel 'wenn du eine Banane siehst, "
                + "nimm sie'." : "What should I do when I see " + what + "? Say, for example, 'when you see a banana, "
                + "take it'.";
    }

    String pronoun(String word, String question) {
        return german() ? "Ich weiß noch nicht, was '" + word + "' ist. " + question
                : "I don't know what '" + word + "' is yet. " + question;
    }

    String notUnderstood(String sentence, List<String> unknown, String hint) {
        if (german()) {
            String because = unknown.isEmpty() ? "" : " (ich kenne " + list(unknown.stream()
                    .map(word -> "'" + word + "'").toList(), "oder") + " nicht)";
            return "Ich habe '" + sentence + "' nicht verstanden" + because + "; " + hint + ".";
        }
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
