package io.orchard.agents.language;

import io.orchard.agents.language.Ask.Topic;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Recognises the questions a person asks an agent ("how many fruits have you got?", "what do you
 * see?", "where is the castle?") by their frames, before the grammar of commands sees the
 * sentence. A frame says the topic; the words it leaves open ("the castle") are a noun phrase the
 * grammar reads. Politeness around a question ("could you tell me ...", "..., do you know?") is
 * dropped, and the first two words are corrected for small typos ("wher are you").
 */
final class Questions {

    /** A question recognised: its topic, the words it names (none when empty) and its addressee. */
    record Frame(Topic topic, List<Tokenizer.Token> about, String addressee) {
    }

    private static final String X = "(?<x>.+?)";

    /** The frames, tried in order; the first that matches the whole sentence wins. */
    private static final List<Map.Entry<Pattern, Topic>> FRAMES = new ArrayList<>();

    /** The frames of German questions. */
    private static final List<Map.Entry<Pattern, Topic>> GERMAN_FRAMES = new ArrayList<>();

    private static final List<String> GERMAN_PREFIXES = List.of("hey", "ok", "okay", "also", "und", "bitte",
            "sag mir", "sag mal", "kannst du mir sagen", "weisst du", "weißt du", "ich frage mich");

    private static final List<String> GERMAN_SUFFIXES = List.of("bitte", "gerade", "jetzt", "eigentlich", "denn",
            "im moment", "momentan", "gerade jetzt", "schon", "bis jetzt", "bisher");

    private static final List<String> PREFIXES = List.of("hey", "ok", "okay", "so", "and", "please", "could you please tell me",
            "could you tell me", "can you tell me", "can you please tell me", "would you mind telling me",
            "would you tell me", "please tell me", "tell me", "i wonder", "i would like to know", "let me know",
            "do you know", "do you happen to know");

    private static final List<String> SUFFIXES = List.of("please", "right now", "now", "so far", "yet", "do you know",
            "at the moment", "then", "again", "exactly", "today", "here", "at all");

    private static final Speller SPELLER;

    static {
        frame(Topic.SEE, "how (many|much) " + X + " (do|can) you see");
        frame(Topic.COLLECTED, "how (many|much) " + X + " (have|did|do) you( \\w+)*");
        frame(Topic.COLLECTED, "how (many|much) " + X + " (have you got|you got|you have)");
        frame(Topic.COLLECTED, "(what|which fruit) (have|did) you (collected|collect|eaten|eat|got|get|picked up|pick up"
                + "|gathered|gather|harvested)");
        frame(Topic.COLLECTED, "what (are|do) you (carrying|holding|have|carry|hold)");
        frame(Topic.COLLECTED, "what is your score");
        frame(Topic.COLLECTED, "have you (picked up|collected|eaten|got|gathered|harvested)( any| some)? " + X);
        frame(Topic.SEE, "what (do|can) you see( around you| in front of you)?");
        frame(Topic.SEE, "what you (can )?see");
        frame(Topic.SEE, "what is (in front of|around|near|ahead of|next to) you");
        frame(Topic.SEE, "(do|can) you see( any| some)? " + X);
        frame(Topic.WHERE, "where are you|where you are|which side of the river are you on"
                + "|what side of the river are you on|are you near the castle");
        frame(Topic.HEADING, "(which|what) (way|direction) are you (facing|looking|heading|going)"
                + "|where are you (facing|looking)");
        frame(Topic.DOING, "what are you doing( and why)?|what are you up to|why are you doing (that|this|it)"
                + "|what is your (goal|plan|task)|what are you (trying to do|working on)|what you are doing"
                + "|how are you doing|how is it going");
        frame(Topic.WHY, "why (did|have) you (stop|stopped|give up|given up|fail|failed|quit|stop moving"
                + "|stopped moving|stop there)|why (are|do|did) not you .*|why are you not .*|what went wrong"
                + "|why did (that|it) (fail|not work)|what happened|why are you (standing|waiting)( still)?");
        frame(Topic.CAN, "what can you do|what do you understand|what can i (say|ask)");
        frame(Topic.RULES, "what are (your|the) (rules|restrictions|conditions)|(what|which) rules (do you have|are you "
                + "(following|keeping|obeying))|do you have any rules|what (rules )?(did|have) i (told|tell|given|give) "
                + "you|what are you not allowed to do|what must you (avoid|not do)|(tell me|list) your rules|your rules"
                + "|what rules do you follow|any rules");
        frame(Topic.WHERE_IS, "where (is|are) " + X);
        frame(Topic.WHERE_IS, "where " + X + " (is|are)");
        frame(Topic.WHERE_IS, "have you seen( any| some)? " + X);
        frame(Topic.WHERE_IS, "(is|are) there( any| some)? " + X);
        frame(Topic.WHERE_IS, "what " + X + " do you know( of| about)?");
        frame(Topic.WHERE_IS, "what do you know (of|about) " + X);
        german(Topic.SEE, "was (siehst du|kannst du sehen)( um dich herum| vor dir)?");
        german(Topic.SEE, "(siehst|kannst) du( irgendwelche| eine| einen| ein| irgendeine| irgendeinen)? " + X
                + "( sehen)?");
        german(Topic.COLLECTED, "wie viele? " + X + " hast du( schon)?( gesammelt| gegessen| aufgehoben| eingesammelt"
                + "| gepfluckt| genommen)?");
        german(Topic.COLLECTED, "was hast du( schon)? (gesammelt|gegessen|aufgehoben|eingesammelt|genommen)"
                + "|was (tragst|traegst) du( bei dir)?|wie (ist|sieht) dein punktestand( aus)?|wie viele punkte hast du");
        german(Topic.COLLECTED, "hast du( schon)?( irgendwelche| eine| einen| ein)? " + X + " (gesammelt|gegessen"
                + "|aufgehoben|genommen)");
        german(Topic.WHERE, "wo bist du|wo befindest du dich|auf welcher seite des flusses bist du");
        german(Topic.HEADING, "in welche richtung (schaust|blickst|siehst|gehst|guckst) du|wohin (schaust|blickst"
                + "|guckst|siehst) du");
        german(Topic.DOING, "was (machst|tust) du( da| gerade| jetzt)?( und warum)?|was hast du vor|woran arbeitest du"
                + "|was ist deine aufgabe");
        german(Topic.WHY, "warum hast du (angehalten|aufgehort|aufgehoert|aufgegeben|gestoppt)|warum (bewegst du "
                + "dich|gehst du) nicht( mehr)?|was ist (schiefgegangen|passiert)|warum stehst du (still|herum|da)"
                + "|warum hat (das|es) nicht (geklappt|funktioniert)");
        german(Topic.CAN, "was kannst du( tun| machen)?|was verstehst du|was kann ich (sagen|fragen)");
        german(Topic.RULES, "was sind deine regeln|welche regeln hast du|hast du regeln|was darfst du nicht( tun)?"
                + "|(sag mir|nenn mir) deine regeln");
        german(Topic.WHERE_IS, "wo (ist|sind|liegt|liegen|steht|stehen) " + X);
        german(Topic.WHERE_IS, "hast du( irgendwelche| eine| einen| ein)? " + X + " gesehen");
        german(Topic.WHERE_IS, "gibt es( hier)?( irgendwelche| eine| einen| ein)? " + X);
        german(Topic.WHERE_IS, "wo " + X + " (ist|sind)");
        Map<String, String> words = new HashMap<>();
        for (String word : List.of("what", "where", "which", "why", "many", "much", "have", "tell", "could",
                "would", "your", "there")) {
            words.put(word, word);
        }
        SPELLER = new Speller(words);
    }

    private Questions() {
    }

    private static void frame(Topic topic, String regex) {
        FRAMES.add(Map.entry(Pattern.compile(regex), topic));
    }

    private static void german(Topic topic, String regex) {
        GERMAN_FRAMES.add(Map.entry(Pattern.compile(regex), topic));
    }

    /** The question these tokens ask; empty when they are not a question the agents answer. */
    static Optional<Frame> read(List<Tokenizer.Token> tokens, Lexicon lexicon) {
        List<Tokenizer.Token> words = new ArrayList<>();
        String addressee = null;
        int start = 0;
        while (start < tokens.size() && tokens.get(start).isWord()
                && List.of("hey", "ok", "okay").contains(tokens.get(start).text())) {
            start++;
        }
        if (start + 1 < tokens.size() && tokens.get(start).isWord() && tokens.get(start).capitalised()
                && tokens.get(start + 1).isPunctuation() && !tokens.get(start + 1).text().equals(".")) {
            addressee = name(tokens.get(start), lexicon);
            start += 2;
        }
        for (Tokenizer.Token token : tokens.subList(start, tokens.size())) {
            if (token.isWord() || token.type() == Tokenizer.Type.NUMBER) {
                words.add(token);
            }
        }
        boolean german = lexicon.language() == Language.GERMAN;
        List<String> text = new ArrayList<>();
        for (int i = 0; i < words.size(); i++) {
            String word = words.get(i).text();
            String corrected = i < 2 && !german ? SPELLER.correct(word) : null;
            text.add(corrected != null && lexicon.entry(word) == null ? corrected : word);
        }
        List<String> prefixes = german ? GERMAN_PREFIXES : PREFIXES;
        List<String> suffixes = german ? GERMAN_SUFFIXES : SUFFIXES;
        int from = 0;
        int to = text.size();
        boolean trimmed = true;
        while (trimmed) {
            trimmed = false;
            for (String prefix : prefixes) {
                List<String> said = List.of(prefix.split(" "));
                if (to - from > said.size() && text.subList(from, from + said.size()).equals(said)) {
                    from += said.size();
                    trimmed = true;
                }
            }
            for (String suffix : suffixes) {
                List<String> said = List.of(suffix.split(" "));
                if (to - from > said.size() && text.subList(to - said.size(), to).equals(said)) {
                    to -= said.size();
                    trimmed = true;
                }
            }
        }
        String sentence = String.join(" ", text.subList(from, to));
        for (Map.Entry<Pattern, Topic> frame : german ? GERMAN_FRAMES : FRAMES) {
            Matcher matcher = frame.getKey().matcher(sentence);
            if (matcher.matches()) {
                List<Tokenizer.Token> about = List.of();
                if (frame.getKey().pattern().contains("?<x>")) {
                    int first = from + wordsBefore(sentence, matcher.start("x"));
                    int last = from + wordsBefore(sentence, matcher.end("x"));
                    about = List.copyOf(words.subList(first, last));
                }
                return Optional.of(new Frame(frame.getValue(), about, addressee));
            }
        }
        return Optional.empty();
    }

    private static int wordsBefore(String sentence, int index) {
        String before = sentence.substring(0, index).strip();
        return before.isEmpty() ? 0 : before.split(" ").length;
    }

    /** An agent's name as the vocabulary spells it ("guppy" is Guppy), or as written. */
    private static String name(Tokenizer.Token token, Lexicon lexicon) {
        Lexicon.Entry entry = lexicon.entry(token.text());
        return entry != null && entry.cat() == Lexeme.Cat.NAME ? entry.lemma() : token.raw();
    }
}
