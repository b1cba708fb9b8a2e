package io.orchard.agents.language;

import io.orchard.agents.language.Lexeme.Cat;
import io.orchard.agents.language.Tokenizer.Token;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

/**
 * The vocabulary: every word the interpreter knows with its category and lemma (synonyms and
 * inflections share a lemma), the phrases it reads as other words ("next to" as {@code near},
 * "a couple of" as {@code 2}, "could you" as nothing), and the agents' names. {@link #read} turns
 * tokens into lexemes: it corrects typos, rewrites phrases, looks words up and drops fillers.
 *
 * <p>Instances are immutable and safe to share between threads.
 */
final class Lexicon {

    /** What a word means: its category, lemma and number. */
    record Entry(Cat cat, String lemma, boolean plural) {
    }

    /** The agents of the paper, known to every interpreter. */
    static final List<String> PAPER_AGENTS = List.of("Dwarf", "Robot", "Bunny", "Guppy", "Roadrunner");

    /** Function words that typos are never corrected into: too many misspellings are a step from them. */
    private static final Set<String> NOT_CORRECTED_INTO = Set.of(
            "your", "you", "have", "what", "that", "this", "with", "will", "would", "could", "should", "were",
            "want", "like", "need", "from", "just", "some", "they", "them", "those", "these", "when", "once",
            "does", "done", "make", "made", "tell", "said", "more", "much", "very", "well", "also", "again",
            "into", "onto", "upon", "than", "over", "down", "here", "there", "where", "whatever", "while",
            "mind", "sure", "okay", "hello", "thanks", "cheers", "good", "nice", "fine", "hold", "hang",
            "able", "same", "whole", "single", "only", "exactly", "really", "still", "away", "about", "ones");

    private static final Builder ENGLISH_WORDS = new Builder().build();
    private static final GermanWords GERMAN_WORDS = new GermanWords().build();

    private static final Lexicon BASE = new Lexicon(ENGLISH_WORDS.words, ENGLISH_WORDS.phrases, PAPER_AGENTS,
            Language.ENGLISH, known(GERMAN_WORDS.words(), GERMAN_WORDS.phrases()), Set.of());

    private static final Lexicon GERMAN = german();

    private final Language language;
    private final Set<String> foreign;
    /** The grammar's own words a vocabulary took from the English one for its phrases: not words of its language. */
    private final Set<String> borrowed;
    private final Map<String, Entry> words;
    private final Map<String, List<String>> phrases;
    private final Set<String> phraseWords;
    private final int longestPhrase;
    private final Speller speller;
    private final List<String> agentNames;

    /**
     * @param foreign the words of the other language: no typo is corrected into a word of this language
     *                when it is a word of that one
     */
    private Lexicon(Map<String, Entry> words, Map<String, List<String>> phrases, List<String> agentNames,
                    Language language, Set<String> foreign, Set<String> borrowed) {
        this.language = language;
        this.borrowed = Set.copyOf(borrowed);
        this.words = Map.copyOf(words);
        this.phrases = Map.copyOf(phrases);
        this.longestPhrase = phrases.keySet().stream().mapToInt(p -> p.split(" ").length).max().orElse(1);
        this.phraseWords = phrases.keySet().stream().flatMap(p -> Arrays.stream(p.split(" ")))
                .collect(Collectors.toSet());
        this.agentNames = List.copyOf(agentNames);
        Map<String, String> meanings = new HashMap<>();
        words.forEach((word, entry) -> {
            if (correctable(word, entry.cat())) {
                meanings.put(word, entry.cat() + ":" + entry.lemma());
            }
        });
        for (String phrase : phrases.keySet()) {
            for (String word : phrase.split(" ")) {
                if (!words.containsKey(word) && correctable(word, Cat.FILLER)) {
                    meanings.put(word, "phrase:" + word);
                }
            }
        }
        this.speller = new Speller(meanings);
        Set<String> others = new HashSet<>(foreign);
        others.removeAll(words.keySet());
        others.removeAll(phraseWords);
        this.foreign = Set.copyOf(others);
    }

    /** Every word of a vocabulary, its own and those of its phrases. */
    private static Set<String> known(Map<String, Entry> words, Map<String, List<String>> phrases) {
        Set<String> known = new HashSet<>(words.keySet());
        phrases.keySet().forEach(phrase -> known.addAll(Arrays.asList(phrase.split(" "))));
        return known;
    }

    /**
     * The German vocabulary: German words and phrases, and the grammar's own words its phrases are
     * read as ("in der Nähe des" is {@code near the}).
     */
    private static Lexicon german() {
        Map<String, Entry> words = new HashMap<>(GERMAN_WORDS.words());
        Set<String> borrowed = new HashSet<>();
        for (List<String> meaning : GERMAN_WORDS.phrases().values()) {
            for (String word : meaning) {
                if (!words.containsKey(word) && !Character.isDigit(word.charAt(0))) {
                    Entry english = ENGLISH_WORDS.words.get(word);
                    if (english == null) {
                        throw new IllegalStateException("a German phrase becomes unknown word '" + word + "'");
                    }
                    words.put(word, english);
                    borrowed.add(word);
                }
            }
        }
        for (String name : PAPER_AGENTS) {
            words.putIfAbsent(name.toLowerCase(Locale.ROOT), new Entry(Cat.NAME, name, false));
        }
        return new Lexicon(words, GERMAN_WORDS.phrases(), PAPER_AGENTS, Language.GERMAN,
                known(ENGLISH_WORDS.words, ENGLISH_WORDS.phrases), borrowed);
    }

    /** The vocabulary of this language with the paper's agents and these names. */
    static Lexicon withAgents(Collection<String> names, Language language) {
        Lexicon base = language == Language.GERMAN ? GERMAN : BASE;
        if (names.isEmpty()) {
            return base;
        }
        Map<String, Entry> words = new HashMap<>(base.words);
        List<String> known = new ArrayList<>(base.agentNames);
        for (String name : names) {
            String key = Tokenizer.tokens(name).stream().filter(Token::isWord).map(Token::text)
                    .reduce("", String::concat);
            if (key.isEmpty() || (words.containsKey(key) && words.get(key).cat() != Cat.NAME)) {
                continue; // a name that is a word of the vocabulary is still a name after "follow"
            }
            if (!words.containsKey(key)) {
                known.add(name.strip());
            }
            words.putIfAbsent(key, new Entry(Cat.NAME, name.strip(), false));
        }
        return new Lexicon(words, base.phrases, known, language, base == GERMAN ? known(ENGLISH_WORDS.words,
                ENGLISH_WORDS.phrases) : known(GERMAN_WORDS.words(), GERMAN_WORDS.phrases()), base.borrowed);
    }

    /** The language of this vocabulary. */
    Language language() {
        return language;
    }

    /** How many of these words are words of this language as written, not of the other language's too. */
    int own(List<Token> tokens) {
        int own = 0;
        for (Token token : tokens) {
            if (token.isWord() && isNative(token.text()) && !shared(token.text())) {
                own++;
            }
        }
        return own;
    }

    /** Whether a word is a word of this language, not one of the grammar's it borrowed. */
    private boolean isNative(String word) {
        return isKnown(word) && !borrowed.contains(word);
    }

    /** Whether a word is a word of both languages ("stop", "halt", the agents' names). */
    private boolean shared(String word) {
        Lexicon other = this.language == Language.GERMAN ? BASE : GERMAN;
        return other != null && other.isNative(word);
    }

    /** The names of the agents this vocabulary knows, in the order they were given. */
    List<String> agentNames() {
        return agentNames;
    }

    /** The entry of a known word, or null. */
    Entry entry(String word) {
        return words.get(word);
    }

    /** The known word a typo stands for, or null. */
    String correct(String word) {
        return speller.correct(word);
    }

    /**
     * The lexemes of these tokens: typos corrected, phrases rewritten, words looked up (unknown ones
     * as {@link Cat#UNKNOWN}), fillers dropped.
     */
    List<Lexeme> read(List<Token> tokens) {
        List<Spelt> spelt = new ArrayList<>(tokens.size());
        for (int i = 0; i < tokens.size(); i++) {
            Token token = tokens.get(i);
            String text = token.text();
            boolean corrected = false;
            if (token.isWord() && !isKnown(text) && !foreign.contains(text)) {
                String correction = speller.correct(text); // never a word of the other language
                if (correction != null) {
                    text = correction;
                    corrected = true;
                }
            }
            spelt.add(new Spelt(text, token, corrected, i));
        }
        joinCompassPairs(spelt);
        List<Lexeme> lexemes = new ArrayList<>();
        int i = 0;
        while (i < spelt.size()) {
            int length = phraseAt(spelt, i);
            if (length > 1) {
                List<Spelt> span = spelt.subList(i, i + length);
                String raw = String.join(" ", span.stream().map(s -> s.token().raw()).toList());
                List<String> fixed = span.stream().filter(Spelt::corrected).map(f -> f.token().raw()).toList();
                String corrected = fixed.isEmpty() ? null : String.join(" ", fixed);
                for (String word : phrases.get(key(span))) {
                    Spelt first = span.get(0);
                    lexemes.add(lexeme(word, raw, first.token().capitalised(), corrected, first.position()));
                }
                i += length;
            } else {
                Spelt s = spelt.get(i);
                Token token = s.token();
                if (token.isPunctuation()) {
                    lexemes.add(new Lexeme(Cat.PUNCT, token.text(), false, 0, token.raw(), false, null, s.position()));
                } else {
                    lexemes.add(lexeme(s.text(), token.raw(), token.capitalised(), s.corrected() ? token.raw() : null,
                            s.position()));
                }
                i++;
            }
        }
        lexemes.removeIf(lexeme -> lexeme.is(Cat.FILLER));
        ordinals(lexemes);
        return lexemes;
    }

    /** Reads "2nd", "3rd", "4th" (a number, then its ending) as ordinals. */
    private static void ordinals(List<Lexeme> lexemes) {
        for (int i = lexemes.size() - 2; i >= 0; i--) {
            Lexeme number = lexemes.get(i);
            Lexeme ending = lexemes.get(i + 1);
            if (number.is(Cat.NUMBER) && ending.is(Cat.UNKNOWN) && List.of("st", "nd", "rd", "th").contains(
                    ending.lemma()) && number.number() == Math.rint(number.number())) {
                lexemes.set(i, new Lexeme(Cat.ORD, number.lemma(), false, number.number(), number.raw() + ending.raw(),
                        false, null, number.position()));
                lexemes.remove(i + 1);
            }
        }
    }

    /** Reads "north east" as "northeast", so that phrases need to know only the one word. */
    private static void joinCompassPairs(List<Spelt> spelt) {
        for (int i = spelt.size() - 2; i >= 0; i--) {
            Spelt first = spelt.get(i);
            Spelt second = spelt.get(i + 1);
            if (first.token().isWord() && second.token().isWord()
                    && (first.text().equals("north") || first.text().equals("south"))
                    && (second.text().equals("east") || second.text().equals("west"))) {
                Token joined = new Token(first.text() + second.text(), first.token().raw() + " " + second.token().raw(),
                        Tokenizer.Type.WORD, first.token().capitalised());
                boolean corrected = first.corrected() || second.corrected();
                spelt.set(i, new Spelt(joined.text(), joined, corrected, first.position()));
                spelt.remove(i + 1);
            }
        }
    }

    private boolean isKnown(String word) {
        return words.containsKey(word) || phraseWords.contains(word);
    }

    /** The length of the longest phrase that starts at {@code start}, or 1. */
    private int phraseAt(List<Spelt> spelt, int start) {
        for (int length = Math.min(longestPhrase, spelt.size() - start); length > 1; length--) {
            List<Spelt> span = spelt.subList(start, start + length);
            if (span.stream().allMatch(s -> s.token().isWord()) && phrases.containsKey(key(span))) {
                return length;
            }
        }
        return 1;
    }

    private static String key(List<Spelt> span) {
        return String.join(" ", span.stream().map(Spelt::text).toList());
    }

    private Lexeme lexeme(String word, String raw, boolean capitalised, String corrected, int position) {
        if (!word.isEmpty() && Character.isDigit(word.charAt(0))) {
            return new Lexeme(Cat.NUMBER, word, false, parseNumber(word), raw, false, corrected, position);
        }
        Entry entry = words.get(word);
        if (entry == null) {
            return new Lexeme(Cat.UNKNOWN, word, false, 0, raw, capitalised, corrected, position);
        }
        double number = entry.cat() == Cat.NUMBER || entry.cat() == Cat.ORD ? Double.parseDouble(entry.lemma()) : 0;
        return new Lexeme(entry.cat(), entry.lemma(), entry.plural(), number, raw, capitalised, corrected, position);
    }

    private static double parseNumber(String digits) {
        try {
            return Double.parseDouble(digits);
        } catch (NumberFormatException e) {
            return Double.MAX_VALUE;
        }
    }

    private static boolean correctable(String word, Cat cat) {
        if (word.length() < 3 || NOT_CORRECTED_INTO.contains(word)) {
            return false;
        }
        return switch (cat) {
            case DET, PRON, ME, NEG, PUNCT, UNKNOWN -> false;
            case FILLER -> word.length() >= 5;
            default -> true;
        };
    }

    /** A token with its spelling corrected. */
    private record Spelt(String text, Token token, boolean corrected, int position) {
    }

    /** Builds the base vocabulary. */
    private static final class Builder {

        private final Map<String, Entry> words = new LinkedHashMap<>();
        private final Map<String, List<String>> phrases = new LinkedHashMap<>();

        Builder build() {
            verbs();
            nouns();
            modifiers();
            functionWords();
            fillers();
            phrases();
            for (String name : PAPER_AGENTS) {
                put(name.toLowerCase(Locale.ROOT), Cat.NAME, name);
            }
            put("rabbit", Cat.NAME, "Bunny");
            for (Map.Entry<String, List<String>> phrase : phrases.entrySet()) {
                for (String word : phrase.getValue()) {
                    if (!words.containsKey(word) && !Character.isDigit(word.charAt(0))) {
                        throw new IllegalStateException("phrase '" + phrase.getKey() + "' becomes unknown word '"
                                + word + "'");
                    }
                }
            }
            return this;
        }

        private void verbs() {
            verb("go", "go", "walk", "run", "head", "move", "travel", "hurry", "jog", "stroll", "march", "navigate",
                    "step", "dash", "rush", "sprint", "trot", "amble", "advance", "hike", "trek", "venture", "scurry");
            irregular("go", "goes", "going", "went", "gone", "ran", "travelling", "traveling", "travelled");
            verb("come", "come");
            irregular("come", "came");
            verb("return", "return");
            verb("cross", "cross", "traverse");
            verb("collect", "collect", "grab", "fetch", "gather", "harvest", "eat", "pluck", "bring", "retrieve",
                    "snatch", "nab", "obtain", "acquire", "munch", "devour", "gobble", "consume", "scoop", "pocket");
            irregular("collect", "ate", "eaten", "brought");
            verb("pick", "pick");
            verb("take", "take");
            irregular("take", "took", "taken");
            verb("get", "get");
            irregular("get", "got", "gotten");
            verb("turn", "turn", "rotate", "spin", "pivot", "swivel");
            irregular("turn", "spun");
            verb("face", "face");
            verb("look", "look", "peek", "glance", "peer", "gaze");
            verb("find", "find", "locate", "seek", "hunt", "spot", "discover");
            irregular("find", "found", "sought");
            verb("search", "search", "scan");
            verb("explore", "explore", "wander", "roam", "scout", "patrol", "investigate", "survey", "prowl", "rove");
            irregular("explore", "patrolling");
            verb("follow", "follow", "chase", "accompany", "tail", "shadow", "track", "pursue", "trail", "escort");
            verb("stop", "stop", "halt", "freeze", "cease", "cancel", "abort", "quit");
            irregular("stop", "froze", "frozen");
            verb("wait", "wait", "stay", "remain", "pause", "linger", "idle");
            verb("carry-on", "continue", "resume", "proceed");
            put("carry-on", Cat.VERB, "carry-on");
            verb("enter", "enter");
            verb("approach", "approach", "reach", "visit");
            verb("keep", "keep");
            irregular("keep", "kept");
            verb("start", "start", "begin");
            irregular("start", "began", "begun", "beginning");
            verb("do", "do", "make", "perform");
            irregular("do", "does", "did", "done", "made");
            verb("use", "use");
            verb("leave", "leave", "ignore", "skip", "disregard", "spare");
            verb("avoid", "avoid", "shun", "evade", "dodge");
            verb("forget", "forget");
            irregular("forget", "forgot", "forgotten", "forgetting");
            verb("lift", "lift", "drop", "clear", "remove", "scrap", "revoke", "withdraw", "reset");
        }

        private void nouns() {
            put("stuff", Cat.NOUN, "fruit", true);
            put("fruit", Cat.NOUN, "fruit", true);
            put("food", Cat.NOUN, "fruit", true);
            noun("fruit", "fruit", "fruits", "food", "foods", "snack", "snacks", "thing", "things", "item", "items");
            noun("fruit", "something", null, "anything", null);
            noun("tomato", "tomato", "tomatoes", "tomatos", "tomatoes");
            noun("banana", "banana", "bananas");
            noun("coconut", "coconut", "coconuts");
            noun("tree", "tree", "trees", "palm", "palms", "oak", "oaks");
            noun("table", "table", "tables", "desk", "desks", "bench", "benches");
            noun("castle", "castle", "castles", "fort", "forts", "fortress", "fortresses", "palace", "palaces");
            noun("river", "river", "rivers", "stream", "streams", "creek", "creeks", "brook", "brooks",
                    "water", "waters");
            noun("bridge", "bridge", "bridges");
            noun("forest", "forest", "forests", "woods", "woods", "wood", "woods", "jungle", "jungles",
                    "grove", "groves", "orchard", "orchards");
            noun("agent", "agent", "agents", "bot", "bots", "creature", "creatures", "player", "players",
                    "someone", null, "somebody", null, "anyone", null, "anybody", null);
            noun("place", "area", "areas", "region", "regions", "zone", "zones", "place", "places",
                    "surroundings", "surroundings", "vicinity", null, "neighbourhood", null, "neighborhood", null,
                    "part", "parts");
            noun("world", "world", null, "map", null, "everywhere", null, "anywhere", null);
            noun("ground", "ground", null, "floor", null);
            noun("start", "start-point", null);
        }

        private void modifiers() {
            words(Cat.SIZE, "big", "big", "bigger", "large", "larger", "huge", "giant", "great", "tall", "taller",
                    "massive", "enormous", "fat", "high");
            words(Cat.SIZE, "small", "small", "smaller", "little", "tiny", "short", "shorter", "mini", "wee", "low");
            words(Cat.SIZE, "largest", "largest", "biggest", "tallest", "greatest");
            words(Cat.SIZE, "smallest", "smallest", "tiniest", "littlest", "shortest");
            words(Cat.DIST, "highest", "highest", "topmost", "uppermost");
            words(Cat.DIST, "lowest", "lowest", "bottommost");
            words(Cat.DIST, "northernmost", "northernmost", "northmost", "northern");
            words(Cat.DIST, "southernmost", "southernmost", "southmost", "southern");
            words(Cat.DIST, "easternmost", "easternmost", "eastmost", "eastern");
            words(Cat.DIST, "westernmost", "westernmost", "westmost", "western");
            words(Cat.DIST, "nearest", "nearest", "closest", "nearer", "closer");
            words(Cat.DIST, "farthest", "farthest", "furthest", "farther", "further", "remotest");
            words(Cat.DIST, "leftmost", "leftmost");
            words(Cat.DIST, "rightmost", "rightmost");
            String[] ordinals = {"third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth",
                "eleventh", "twelfth", "thirteenth", "fourteenth", "fifteenth", "sixteenth", "seventeenth",
                "eighteenth", "nineteenth", "twentieth"};
            for (int n = 0; n < ordinals.length; n++) {
                put(ordinals[n], Cat.ORD, Integer.toString(n + 3)); // "second" is a unit of time too: see NounPhrases
            }
            words(Cat.RULE, "rule", "rule", "rules", "restriction", "restrictions", "constraint", "constraints",
                    "limit", "limits", "condition", "conditions");
            words(Cat.ONLY, "only", "only", "ony", "solely", "exclusively");
            words(Cat.AGAIN, "again", "again");
            words(Cat.COND, "when", "when", "whenever", "if", "unless");
            String[] numbers = {"zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
                "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen",
                "nineteen", "twenty"};
            for (int n = 0; n < numbers.length; n++) {
                put(numbers[n], Cat.NUMBER, Integer.toString(n));
            }
            put("thirty", Cat.NUMBER, "30");
            put("forty", Cat.NUMBER, "40");
            put("fifty", Cat.NUMBER, "50");
            put("ninety", Cat.NUMBER, "90");
            put("hundred", Cat.NUMBER, "100");
            put("dozen", Cat.NUMBER, "12");
            put("several", Cat.NUMBER, "3");
            put("once", Cat.FILLER, "once");
            words(Cat.QUANT, "all", "all");
            words(Cat.QUANT, "every", "every", "each");
            words(Cat.QUANT, "both", "both");
            words(Cat.QUANT, "some", "some");
            words(Cat.QUANT, "everything", "everything");
            words(Cat.DET, "the", "the", "teh", "hte", "whatever", "whichever", "this", "that", "these", "those",
                    "my", "your", "our", "its", "their");
            words(Cat.DET, "a", "a", "an", "any", "another");
            words(Cat.DIR, "north", "north", "northward", "northwards", "northerly");
            words(Cat.DIR, "south", "south", "southward", "southwards", "southerly");
            words(Cat.DIR, "east", "east", "eastward", "eastwards", "easterly");
            words(Cat.DIR, "west", "west", "westward", "westwards", "westerly");
            words(Cat.DIR, "north-east", "northeast", "northeastern", "northeastward");
            words(Cat.DIR, "north-west", "northwest", "northwestern", "northwestward");
            words(Cat.DIR, "south-east", "southeast", "southeastern", "southeastward");
            words(Cat.DIR, "south-west", "southwest", "southwestern", "southwestward");
            words(Cat.SIDE, "left", "left", "leftward", "leftwards");
            words(Cat.SIDE, "right", "right", "rightward", "rightwards");
            words(Cat.SIDE, "forward", "forward", "forwards", "onward", "onwards");
            words(Cat.SIDE, "straight", "straight");
            words(Cat.SIDE, "ahead", "ahead");
            words(Cat.SIDE, "backward", "backward", "backwards", "backwardly");
            words(Cat.UNIT, "degree", "degree", "degrees", "deg", "degs");
            // A world unit is a metre: "go north 20 metres", "walk 5 m to the left".
            words(Cat.UNIT, "metre", "metre", "metres", "meter", "meters", "m", "unit", "units", "pace", "paces");
            words(Cat.UNIT, "second", "second", "seconds", "sec", "secs");
            words(Cat.UNIT, "minute", "minute", "minutes", "min", "mins");
            words(Cat.UNIT, "hour", "hour", "hours");
            words(Cat.UNIT, "moment", "moment", "moments", "instant", "jiffy");
            words(Cat.UNIT, "while", "while");
            words(Cat.UNIT, "bit", "bit", "slightly", "tad");
            words(Cat.UNIT, "twice", "twice");
        }

        private void functionWords() {
            words(Cat.PREP, "to", "to", "towards", "toward", "unto");
            words(Cat.PREP, "on", "on", "onto", "upon", "atop");
            words(Cat.PREP, "in", "in", "into", "inside", "within", "among", "amongst", "amid");
            words(Cat.PREP, "under", "under", "beneath", "below", "underneath");
            words(Cat.PREP, "near", "near", "beside", "besides", "nearby", "alongside", "along");
            words(Cat.PREP, "beyond", "beyond", "behind", "past", "opposite");
            words(Cat.PREP, "from", "from", "off");
            words(Cat.PREP, "around", "around", "round", "about");
            words(Cat.PREP, "through", "through", "thru");
            for (String prep : List.of("of", "for", "with", "up", "down", "back", "away", "out", "over", "across",
                    "after", "before", "at", "by", "via", "until", "till", "this-side", "on-ground", "on-left", "on-right",
                    "in-front", "behind-me", "near-me")) {
                put(prep, Cat.PREP, prep);
            }
            words(Cat.HERE, "here", "here");
            words(Cat.HERE, "there", "there");
            words(Cat.HERE, "home", "home", "base");
            words(Cat.PRON, "it", "it");
            words(Cat.PRON, "them", "them", "they");
            words(Cat.PRON, "him", "him", "her", "he", "she");
            words(Cat.PRON, "one", "ones");
            words(Cat.ME, "me", "me", "us", "myself");
            words(Cat.CONN, "and", "and", "plus");
            words(Cat.CONN, "then", "then", "afterwards", "afterward", "next", "finally", "lastly", "later",
                    "thereafter", "subsequently", "secondly", "thirdly");
            words(Cat.NEG, "not", "not", "never");
        }

        private void fillers() {
            for (String filler : List.of(
                    "please", "pls", "plz", "pleas", "kindly", "now", "quickly", "fast", "slowly", "carefully",
                    "immediately", "soon", "also", "too", "just", "really", "ok", "okay", "hey", "hi",
                    "hello", "yo", "so", "well", "oh", "um", "uh", "alright", "thanks", "thx", "cheers", "buddy",
                    "mate", "friend", "pal", "dude", "you", "yourself", "i", "am", "is", "are", "be", "been", "was",
                    "have", "has", "had", "would", "could", "can", "should", "must", "shall", "may", "might", "will",
                    "which", "who", "lies", "lie", "lying", "hangs", "hang", "hanging", "sits", "sitting",
                    "located", "placed", "standing", "stands", "growing", "grows", "red", "yellow", "brown",
                    "green", "ripe", "juicy", "tasty", "delicious", "fresh", "lovely", "nice", "good", "yummy",
                    "sweet", "old", "pretty", "beautiful", "whole", "single", "very", "exactly", "no", "alone", "be",
                    "yes", "first", "firstly", "initially", "finished", "other",
                    "instead", "asap", "right", "directly", "somewhere", "fell", "fallen", "dropped", "rests",
                    "resting",
                    "rolled", "visible", "available", "closely", "due", "gently", "safely")) {
                if (!words.containsKey(filler)) {
                    put(filler, Cat.FILLER, filler);
                }
            }
        }

        private void phrases() {
            // politeness and framing, read as nothing
            for (String polite : List.of("thank you", "thank you very much", "if you can", "if you could",
                    "if possible", "if you please", "when you can", "right now",
                    "right away", "at once", "straight away", "for me", "i want you to", "i would like you to",
                    "i need you to", "i want to", "i would like to", "you need to", "you have to", "you should",
                    "you must", "need to", "have to", "got to", "try to", "try and", "make sure to",
                    "make sure you", "be sure to", "would you mind", "do you mind", "how about", "what about",
                    "why not", "let us", "go ahead and", "could you please", "be a dear and", "on your own",
                    "by yourself", "by itself", "for a start", "first of all", "to begin with", "to start with",
                    "first off", "before anything else", "at first", "first thing", "all by yourself",
                    "until i say so", "until i tell you", "until i tell you otherwise", "until further notice",
                    "until told", "until i come back", "until i return", "as well", "in place")) {
                phrase(polite, "");
            }
            for (String polite : List.of("would you be so kind as to", "be so kind as to", "be so kind and",
                    "would you be so kind and", "do me a favour and", "do me a favor and", "i would really like you to",
                    "i would really like", "i really want you to", "i really need you to", "i would love you to",
                    "i would love it if you would", "i would love it if you could", "it would be great if you could",
                    "it would be nice if you could", "i wonder if you could", "i was wondering if you could")) {
                phrase(polite, "");
            }
            // rules that last until lifted, and conditions
            for (String lasting : List.of("from now on", "from now", "starting now", "from here on",
                    "from here on in", "for the rest of the game", "for good", "any more", "any longer", "for now on",
                    "until the end of the game", "till the end of the game", "for the whole game")) {
                phrase(lasting, "lasting");
            }
            words(Cat.LASTING, "lasting", "lasting", "always", "henceforth", "hereafter", "anymore");
            phrase("no more", "not lasting");
            phrase("no longer", "not lasting");
            phrase("nothing but", "only");
            phrase("nothing except", "only");
            for (String permit : List.of("you can", "you may", "you are allowed to", "you are free to",
                    "feel free to", "it is ok to", "it is okay to", "it is fine to", "you are permitted to",
                    "you can now", "you may now")) {
                phrase(permit, "permit");
            }
            put("permit", Cat.PERMIT, "permit");
            for (String condition : List.of("when", "whenever", "if", "as soon as", "each time", "every time",
                    "any time", "anytime", "once", "in case", "should", "the moment", "every time that",
                    "each time that")) {
                for (String sight : List.of("see", "find", "spot", "notice", "meet", "encounter", "come across",
                        "run into", "catch sight of", "come upon", "stumble upon", "discover")) {
                    phrase(condition + " you " + sight, "when-see");
                }
            }
            for (String there : List.of("if there is", "if there are", "whenever there is", "whenever there are",
                    "when there is", "when there are")) {
                phrase(there, "when-see");
            }
            put("when-see", Cat.COND, "when-see");
            phrase("stay away from", "avoid near");
            phrase("keep away from", "avoid near");
            phrase("stay well away from", "avoid near");
            phrase("keep well away from", "avoid near");
            phrase("stay clear of", "avoid near");
            phrase("keep clear of", "avoid near");
            phrase("steer clear of", "avoid near");
            phrase("keep your distance from", "avoid near");
            phrase("keep off", "avoid");
            phrase("stay off", "avoid");
            phrase("stay out of", "avoid");
            phrase("keep out of", "avoid");
            phrase("keep to this side of", "wait this-side");
            phrase("keep to this side", "wait this-side");
            phrase("keep on this side of", "wait this-side");
            phrase("keep on this side", "wait this-side");
            phrase("keep to your side of", "wait this-side");
            phrase("leave alone", "leave");
            for (String side : List.of("left", "right")) {
                phrase("from the " + side, side + "most");
                phrase("from " + side, side + "most");
                phrase("counting from the " + side, side + "most");
                phrase("counted from the " + side, side + "most");
                phrase("furthest to the " + side, side + "most");
                phrase("farthest to the " + side, side + "most");
            }
            phrase("left most", "leftmost");
            phrase("right most", "rightmost");
            phrase("you can reach", "");
            phrase("you are able to reach", "");
            phrase("within reach", "");
            phrase("go and stand", "go");
            phrase("go stand", "go");
            for (String direction : List.of("north", "south", "east", "west", "northeast", "northwest",
                    "southeast", "southwest")) {
                phrase("to the " + direction + " side of", "to " + direction + " of");
                phrase("to the " + direction + " side", "to " + direction);
            }
            // connectives
            for (String then : List.of("and then", "after that", "after this", "and after that", "and afterwards",
                    "when you are done", "when you are finished", "when done", "once done", "once you are done",
                    "when finished", "once finished", "after you are done", "followed by", "and finally",
                    "and next", "when you have done that", "once you have done that", "when that is done",
                    "then after that", "and later")) {
                phrase(then, "then");
            }
            phrase("as well as", "and");
            phrase("along with", "and");
            // going
            phrase("make your way", "go");
            phrase("find your way", "go");
            phrase("get yourself", "go");
            phrase("carry on", "carry-on");
            phrase("carry on with", "carry-on");
            phrase("carry on with what you were doing", "carry-on");
            phrase("what you were doing", "");
            phrase("with your work", "");
            phrase("your work", "");
            phrase("get to work", "carry-on");
            phrase("get going", "carry-on");
            for (String autonomy : List.of("autonomy", "autonomous mode", "being autonomous", "your own devices")) {
                phrase("go back to " + autonomy, "carry-on");
                phrase("return to " + autonomy, "carry-on");
                phrase("back to " + autonomy, "carry-on");
                phrase("switch to " + autonomy, "carry-on");
                phrase("resume " + autonomy, "carry-on");
            }
            phrase("go autonomous", "carry-on");
            phrase("act autonomously", "carry-on");
            phrase("be independent", "carry-on");
            phrase("to you", "");
            phrase("from under", "under");
            phrase("from underneath", "under");
            phrase("from beneath", "under");
            phrase("from below", "under");
            phrase("from inside", "in");
            phrase("from on top of", "on");
            phrase("from on", "on");
            phrase("from in", "in");
            phrase("get moving", "carry-on");
            phrase("something to eat", "something");
            phrase("anything to eat", "anything");
            phrase("until there are none left", "");
            phrase("until there is none left", "");
            phrase("until none are left", "");
            phrase("until you have them all", "");
            for (String speed : List.of("fast", "quickly", "soon")) {
                phrase("as " + speed + " as you can", "");
                phrase("as " + speed + " as possible", "");
                phrase("as " + speed + " as you could", "");
            }
            phrase("you see", "");
            phrase("until you find", "until find");
            phrase("until you see", "until find");
            phrase("until you spot", "until find");
            phrase("you can see", "");
            phrase("you find", "");
            phrase("you can find", "");
            phrase("you come across", "");
            phrase("you know of", "");
            phrase("in sight", "");
            for (String start : List.of("where you started", "where you began", "where you started from",
                    "where you began from", "your starting point", "the starting point", "the start",
                    "your start", "where you started the game", "your starting place", "the starting place")) {
                phrase(start, "start-point");
            }
            // places relative to the agent, from its heading
            for (String side : List.of("left", "right")) {
                for (String said : List.of("at your %s", "on your %s hand side",
                        "on your %s side", "to the %s of you", "on the %s of you", "on the %s side of you")) {
                    phrase(String.format(said, side), "on-" + side);
                }
            }
            for (String said : List.of("in front of you", "ahead of you", "in front of yourself")) {
                phrase(said, "in-front");
            }
            for (String said : List.of("near you", "around you", "close to you", "next to you", "by you",
                    "beside you", "near yourself", "around yourself", "close by you", "near me", "around me",
                    "close to me", "next to me")) {
                phrase(said, "near-me");
            }
            phrase("where you came from", "home");
            phrase("where you were", "home");
            phrase("where you were before", "home");
            phrase("the other way", "around");
            phrase("the opposite way", "around");
            phrase("the other direction", "around");
            phrase("the opposite direction", "around");
            phrase("behind you", "behind-me");
            phrase("behind yourself", "behind-me");
            phrase("as you were", "carry-on");
            phrase("do your thing", "carry-on");
            phrase("do your own thing", "carry-on");
            phrase("do whatever you want", "carry-on");
            phrase("do whatever you like", "carry-on");
            phrase("do what you want", "carry-on");
            phrase("do what you like", "carry-on");
            phrase("be autonomous", "carry-on");
            phrase("be free", "carry-on");
            phrase("you are free", "carry-on");
            phrase("you are on your own", "carry-on");
            phrase("back to work", "carry-on");
            phrase("get back to work", "carry-on");
            phrase("go back to work", "carry-on");
            phrase("back to what you were doing", "carry-on");
            phrase("go back to what you were doing", "carry-on");
            phrase("keep on", "keep");
            phrase("step back", "go backward");
            phrase("move back", "go backward");
            phrase("back up", "go backward");
            phrase("back off", "go backward");
            phrase("take a step back", "go backward");
            phrase("take a step forward", "go forward");
            phrase("using the", "via the");
            phrase("using a", "via a");
            phrase("by using the", "via the");
            phrase("by way of", "via");
            phrase("stand still", "stop");
            phrase("hold it", "stop");
            phrase("stop it", "stop");
            phrase("that is enough", "stop");
            phrase("enough", "stop");
            phrase("never mind", "stop");
            phrase("nevermind", "stop");
            phrase("stop what you are doing", "stop");
            phrase("stay where you are", "wait here");
            phrase("stay right there", "wait here");
            phrase("stay right here", "wait here");
            phrase("where you are", "here");
            phrase("stay put", "wait here");
            phrase("hold on", "wait");
            phrase("hang on", "wait");
            phrase("stand by", "wait");
            phrase("sit tight", "wait");
            phrase("hold still", "wait");
            phrase("hold your position", "wait");
            phrase("hold position", "wait");
            phrase("do not move", "wait");
            phrase("not move", "wait");
            phrase("do not", "not");
            phrase("does not", "not");
            phrase("over here", "here");
            phrase("right here", "here");
            phrase("over there", "there");
            phrase("right there", "there");
            phrase("about face", "turn around");
            phrase("about turn", "turn around");
            phrase("u turn", "around");
            phrase("uturn", "around");
            phrase("a u turn", "around");
            phrase("a uturn", "around");
            phrase("to the left", "left");
            phrase("to the right", "right");
            phrase("to your left", "left");
            phrase("to your right", "right");
            phrase("on your left", "left");
            phrase("on your right", "right");
            phrase("a little", "bit");
            phrase("a little bit", "bit");
            phrase("a bit", "bit");
            phrase("a tad", "bit");
            phrase("a while", "while");
            phrase("for a while", "for while");
            phrase("for a bit", "for bit");
            phrase("for a moment", "for moment");
            phrase("a moment", "moment");
            // collecting
            phrase("pickup", "pick up");
            phrase("give me", "fetch me");
            phrase("hand me", "fetch me");
            phrase("get me", "fetch me");
            phrase("bring me", "fetch me");
            phrase("i want", "fetch");
            phrase("i need", "fetch");
            phrase("i would like", "fetch");
            phrase("back to me", "");
            phrase("as many", "all");
            phrase("as much", "all");
            phrase("as you can", "");
            phrase("as you can find", "");
            phrase("as possible", "");
            phrase("all you can find", "all");
            phrase("everything you can find", "everything");
            phrase("all of the", "all");
            phrase("all the", "all");
            phrase("all of", "all");
            phrase("every single", "every");
            phrase("each and every", "every");
            phrase("each of the", "every");
            phrase("every one of the", "every");
            phrase("a couple of", "2");
            phrase("a couple", "2");
            phrase("couple of", "2");
            phrase("a pair of", "2");
            phrase("a few", "3");
            phrase("a dozen", "12");
            phrase("half a dozen", "6");
            phrase("a handful of", "5");
            // looking
            phrase("look for", "find");
            phrase("look out for", "find");
            phrase("search for", "find");
            phrase("hunt for", "find");
            phrase("seek out", "find");
            phrase("track down", "find");
            phrase("keep an eye out for", "find");
            phrase("look around", "explore");
            phrase("look about", "explore");
            phrase("look round", "explore");
            phrase("have a look around", "explore");
            phrase("take a look around", "explore");
            phrase("have a look round", "explore");
            phrase("have a look", "explore");
            phrase("take a look", "explore");
            phrase("have a look at", "look at");
            phrase("take a look at", "look at");
            phrase("go exploring", "explore");
            phrase("go explore", "explore");
            phrase("poke around", "explore");
            phrase("stay with", "follow");
            phrase("stick with", "follow");
            phrase("keep up with", "follow");
            phrase("go with", "follow");
            phrase("go along with", "follow");
            phrase("come with", "follow");
            phrase("come along with", "follow");
            phrase("tag along with", "follow");
            phrase("go after", "follow");
            phrase("run after", "follow");
            // places
            phrase("next to", "near");
            phrase("right next to", "near");
            phrase("close to", "near");
            phrase("near to", "near");
            phrase("close by", "near");
            phrase("not far from", "near");
            phrase("in front of", "near");
            phrase("in the vicinity of", "near");
            phrase("right by", "near");
            phrase("on top of", "on");
            phrase("up in", "in");
            phrase("high in", "in");
            phrase("high up in", "in");
            phrase("out of", "from");
            phrase("off of", "from");
            phrase("down from", "from");
            phrase("on the ground", "on-ground");
            phrase("on the floor", "on-ground");
            phrase("from the ground", "on-ground");
            phrase("off the ground", "on-ground");
            phrase("from the floor", "on-ground");
            phrase("off the floor", "on-ground");
            for (String far : List.of("other", "far", "opposite")) {
                phrase("on the " + far + " side of", "beyond");
                phrase("the " + far + " side of", "beyond");
                phrase("to the " + far + " side of", "to beyond");
                phrase("over the " + far + " side of", "beyond");
                phrase("on the " + far + " side", "beyond");
                phrase("the " + far + " side", "beyond");
                phrase("to the " + far + " side", "to beyond");
                phrase(far + " side of", "beyond");
            }
            phrase("over to the other side", "to beyond");
            phrase("over to the other side of", "to beyond");
            phrase("across from", "beyond");
            for (String near : List.of("this", "our", "my", "the near", "the same", "the nearer")) {
                phrase("on " + near + " side of", "this-side");
                phrase(near + " side of", "this-side");
                phrase("on " + near + " side", "this-side");
            }
            phrase("road runner", "roadrunner");
            phrase("the road runner", "roadrunner");
            phrase("palm tree", "tree");
            phrase("palm trees", "trees");
            phrase("picnic table", "table");
            phrase("picnic tables", "tables");
            phrase("most distant", "farthest");
            phrase("far away", "");
            phrase("far off", "");
            phrase("the whole world", "world");
            phrase("lying around", "");
            for (String direction : List.of("north", "south", "east", "west", "northeast", "northwest",
                    "southeast", "southwest")) {
                phrase("to the " + direction, direction);
                phrase("towards the " + direction, direction);
                phrase("toward the " + direction, direction);
                phrase("in the " + direction, direction);
                phrase("up " + direction, direction);
                phrase("down " + direction, direction);
                phrase("the " + direction + " side of", direction + " of");
                phrase("on the " + direction + " side of", direction + " of");
                phrase("to the " + direction + " of", direction + " of");
                phrase("in the " + direction + " of", direction + " of");
                phrase("on the " + direction + " of", direction + " of");
            }
        }

        private void verb(String lemma, String... bases) {
            for (String base : bases) {
                put(base, Cat.VERB, lemma);
                putIfAbsent(base + (base.matches(".*(s|sh|ch|x|z|o)") ? "es" : "s"), Cat.VERB, lemma);
                putIfAbsent(gerund(base), Cat.VERB, lemma);
                putIfAbsent(past(base), Cat.VERB, lemma);
            }
        }

        private void irregular(String lemma, String... forms) {
            for (String form : forms) {
                putIfAbsent(form, Cat.VERB, lemma);
            }
        }

        private static String gerund(String base) {
            if (base.endsWith("ie")) {
                return base.substring(0, base.length() - 2) + "ying";
            }
            if (base.endsWith("e") && !base.endsWith("ee") && base.length() > 2) {
                return base.substring(0, base.length() - 1) + "ing";
            }
            return (doublesLast(base) ? base + base.charAt(base.length() - 1) : base) + "ing";
        }

        private static String past(String base) {
            if (base.endsWith("e")) {
                return base + "d";
            }
            if (base.matches(".*[^aeiou]y")) {
                return base.substring(0, base.length() - 1) + "ied";
            }
            return (doublesLast(base) ? base + base.charAt(base.length() - 1) : base) + "ed";
        }

        /** Whether a short verb ending consonant-vowel-consonant doubles its last letter: "stop", "stopping". */
        private static boolean doublesLast(String base) {
            int n = base.length();
            return n <= 4 && n >= 3 && !isVowel(base.charAt(n - 1)) && "wxy".indexOf(base.charAt(n - 1)) < 0
                    && isVowel(base.charAt(n - 2)) && !isVowel(base.charAt(n - 3));
        }

        private static boolean isVowel(char c) {
            return "aeiou".indexOf(c) >= 0;
        }

        /** Nouns of one lemma, given as pairs of singular and plural (a null plural for none). */
        private void noun(String lemma, String... pairs) {
            for (int i = 0; i < pairs.length; i += 2) {
                putIfAbsent(pairs[i], Cat.NOUN, lemma);
                if (i + 1 < pairs.length && pairs[i + 1] != null) {
                    putIfAbsent(pairs[i + 1], Cat.NOUN, lemma, true);
                }
            }
        }

        private void words(Cat cat, String lemma, String... surfaces) {
            for (String surface : surfaces) {
                put(surface, cat, lemma);
            }
        }

        private void phrase(String pattern, String replacement) {
            List<String> words = replacement.isEmpty() ? List.of() : List.of(replacement.split(" "));
            if (phrases.put(pattern, words) != null) {
                throw new IllegalStateException("phrase '" + pattern + "' is given twice");
            }
        }

        private void put(String word, Cat cat, String lemma) {
            put(word, cat, lemma, false);
        }

        private void put(String word, Cat cat, String lemma, boolean plural) {
            Entry previous = words.put(word, new Entry(cat, lemma, plural));
            if (previous != null && !previous.equals(new Entry(cat, lemma, plural))) {
                throw new IllegalStateException("word '" + word + "' is both " + previous + " and " + cat + " "
                        + lemma);
            }
        }

        private void putIfAbsent(String word, Cat cat, String lemma) {
            putIfAbsent(word, cat, lemma, false);
        }

        private void putIfAbsent(String word, Cat cat, String lemma, boolean plural) {
            words.putIfAbsent(word, new Entry(cat, lemma, plural));
        }
    }
}
