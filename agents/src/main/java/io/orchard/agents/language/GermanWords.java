package io.orchard.agents.language;

import io.orchard.agents.language.Lexeme.Cat;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The German vocabulary: each German word or phrase read as the word of the grammar it means
 * ("nimm" is {@code take}, "Kokosnüsse" is {@code coconut} plural, "in der Nähe des" is
 * {@code near the}), so that German sentences become the same goals as English ones. Words are
 * written here as German spells them; each is known with its umlauts and ß written plainly too
 * ("Brücke", "brucke", "bruecke"; "groß", "gross"), as people type without them.
 */
final class GermanWords {

    private final Map<String, Lexicon.Entry> words = new LinkedHashMap<>();
    private final Map<String, List<String>> phrases = new LinkedHashMap<>();

    /** The words, keyed as the tokenizer writes them. */
    Map<String, Lexicon.Entry> words() {
        return words;
    }

    /** The phrases, keyed as the tokenizer writes their words, with the words of the grammar they mean. */
    Map<String, List<String>> phrases() {
        return phrases;
    }

    GermanWords build() {
        verbs();
        nouns();
        modifiers();
        functionWords();
        fillers();
        sayings();
        return this;
    }

    private void verbs() {
        verb("go", "geh", "gehe", "gehen", "gehst", "geht", "lauf", "laufe", "laufen", "läufst", "renn", "renne",
                "rennen", "spazier", "spaziere", "marschier", "marschiere", "beweg", "bewege", "bewegen", "eil", "eile",
                "flitz", "flitze", "fahr", "fahre", "fahren", "wandere", "wander", "begib", "schlender", "schlendere",
                "trab", "trabe");
        verb("come", "komm", "komme", "kommen", "kommst");
        verb("return", "kehr", "kehre");
        verb("cross", "überquere", "überquer", "überqueren", "überquerst", "quere", "quer");
        verb("collect", "sammle", "sammel", "sammeln", "sammelst", "hol", "hole", "holen", "holst", "bring", "bringe",
                "bringen", "bringst", "iss", "esse", "essen", "isst", "friss", "fresse", "pflück", "pflücke",
                "pflücken", "ernte", "ernten", "schnapp", "schnappe", "besorg", "besorge", "besorgen", "verspeise");
        verb("take", "nimm", "nehme", "nehmen", "nimmst", "greif", "greife", "greifen");
        verb("pick", "heb", "hebe", "heben", "hebst");
        verb("turn", "dreh", "drehe", "drehen", "drehst", "wend", "wende", "wenden");
        verb("look", "schau", "schaue", "schauen", "schaust", "guck", "gucke", "gucken", "sieh", "siehe", "blick",
                "blicke", "blicken");
        verb("see", "siehst", "sehen", "findest", "entdeckst", "triffst", "bemerkst", "erblickst", "begegnest");
        verb("find", "finde", "finden", "such", "suche", "suchen", "suchst", "entdecke");
        verb("explore", "erkunde", "erkunden", "erkundest", "erforsche", "erforschen", "durchsuche", "durchsuchen",
                "streif", "streife", "patrouilliere");
        verb("follow", "folge", "folg", "folgen", "folgst", "verfolge", "verfolgen", "begleite", "begleiten");
        verb("stop", "stopp", "stoppe", "stoppen", "stop", "anhalten", "angehalten");
        verb("wait", "warte", "wart", "warten", "wartest", "bleib", "bleibe", "bleiben");
        verb("carry-on", "weitermachen", "fortfahren");
        verb("enter", "betritt", "betrete", "betreten");
        verb("do", "mach", "mache", "machen", "tu", "tue");
        verb("use", "benutze", "benutz", "nutze", "nutz", "verwende");
        verb("leave", "lass", "lasse", "ignoriere", "ignorier", "ignorieren", "verschone");
        verb("avoid", "meide", "meiden", "vermeide", "vermeiden");
        verb("forget", "vergiss", "vergesse", "vergessen");
        verb("keep", "halte");
    }

    private void nouns() {
        noun("fruit", "frucht obst ding etwas irgendwas", "früchte früchten dinge dingen sachen");
        noun("tomato", "tomate", "tomaten");
        noun("banana", "banane", "bananen");
        noun("coconut", "kokosnuss kokosnuß kokos", "kokosnüsse kokosnüssen");
        noun("tree", "baum baumes baums palme", "bäume bäumen palmen");
        noun("table", "tisch tisches", "tische tischen");
        noun("castle", "schloss schlosses schloß schlosse burg festung", "schlösser burgen");
        noun("river", "fluss flusses fluß flusse bach wasser strom stroms", "flüsse flüssen");
        noun("bridge", "brücke", "brücken");
        noun("forest", "wald walde waldes wäldchen hain", "wälder wäldern");
        noun("agent", "agent jemand jemanden jemandem spieler", "agenten");
        noun("place", "gegend bereich gebiet ort stelle umgebung seite", "gegenden");
        noun("world", "welt überall karte", "welten");
        noun("ground", "boden erde", "böden");
        noun("start", "startpunkt ausgangspunkt anfang startplatz start", "startpunkte");
        for (String[] name : new String[][] {{"roboter", "Robot"}, {"zwerg", "Dwarf"}, {"hase", "Bunny"},
            {"hasen", "Bunny"}, {"kaninchen", "Bunny"}, {"rennkuckuck", "Roadrunner"}}) {
            put(name[0], Cat.NAME, name[1], false);
        }
    }

    private void modifiers() {
        word(Cat.SIZE, "big", "groß", "große", "großen", "großer", "großes", "großem", "hoch", "hohe", "hohen",
                "hoher", "hohes", "riesig", "riesige", "riesigen");
        word(Cat.SIZE, "small", "klein", "kleine", "kleinen", "kleiner", "kleines", "kleinem", "niedrig", "niedrige");
        word(Cat.SIZE, "largest", "größte", "größten", "größter", "größtes", "größtem");
        word(Cat.SIZE, "smallest", "kleinste", "kleinsten", "kleinster", "kleinstes", "kleinstem");
        word(Cat.DIST, "nearest", "nächste", "nächsten", "nächster", "nächstes", "nächstem", "nächstgelegene",
                "nächstgelegenen", "naheste", "nahesten");
        word(Cat.DIST, "farthest", "weiteste", "weitesten", "entfernteste", "entferntesten", "fernste", "fernsten");
        word(Cat.DIST, "highest", "höchste", "höchsten", "höchster", "höchstes");
        word(Cat.DIST, "lowest", "niedrigste", "niedrigsten", "tiefste", "tiefsten", "unterste", "untersten");
        word(Cat.DIST, "northernmost", "nördliche", "nördlichen", "nördlichste", "nördlichsten");
        word(Cat.DIST, "southernmost", "südliche", "südlichen", "südlichste", "südlichsten");
        word(Cat.DIST, "easternmost", "östliche", "östlichen", "östlichste", "östlichsten");
        word(Cat.DIST, "westernmost", "westliche", "westlichen", "westlichste", "westlichsten");
        word(Cat.DIST, "leftmost", "linke", "linken", "linkeste");
        word(Cat.DIST, "rightmost", "rechte", "rechten");
        String[] numbers = {"null", "eins", "zwei", "drei", "vier", "fünf", "sechs", "sieben", "acht", "neun", "zehn",
            "elf", "zwölf", "dreizehn", "vierzehn", "fünfzehn", "sechzehn", "siebzehn", "achtzehn", "neunzehn",
            "zwanzig"};
        for (int n = 0; n < numbers.length; n++) {
            put(numbers[n], Cat.NUMBER, Integer.toString(n), false);
        }
        put("dreißig", Cat.NUMBER, "30", false);
        put("vierzig", Cat.NUMBER, "40", false);
        put("fünfzig", Cat.NUMBER, "50", false);
        put("neunzig", Cat.NUMBER, "90", false);
        put("hundert", Cat.NUMBER, "100", false);
        put("dutzend", Cat.NUMBER, "12", false);
        String[] ordinals = {"zweit", "dritt", "viert", "fünft", "sechst", "siebt", "acht", "neunt", "zehnt", "elft",
            "zwölft", "dreizehnt", "vierzehnt", "fünfzehnt", "sechzehnt", "siebzehnt", "achtzehnt", "neunzehnt",
            "zwanzigst"};
        for (int n = 0; n < ordinals.length; n++) {
            for (String ending : List.of("e", "en", "er", "es", "em")) {
                putIfAbsent(ordinals[n] + ending, Cat.ORD, Integer.toString(n + 2));
            }
        }
        word(Cat.QUANT, "all", "alle", "allen", "aller", "sämtliche", "sämtlichen");
        word(Cat.QUANT, "every", "jede", "jeden", "jeder", "jedes", "jedem");
        word(Cat.QUANT, "both", "beide", "beiden");
        word(Cat.QUANT, "some", "einige", "einigen", "manche", "mehrere");
        word(Cat.QUANT, "everything", "alles");
        word(Cat.DET, "the", "der", "die", "das", "den", "dem", "des", "diese", "diesen", "dieser", "dieses",
                "diesem", "jene", "jenen", "jener", "jenes", "jenem", "mein", "meine", "meinen", "meinem", "dein",
                "deine", "deinen", "deinem", "deiner", "deines");
        word(Cat.DET, "a", "ein", "eine", "einen", "einem", "einer", "eines", "irgendein", "irgendeine",
                "irgendeinen", "irgendeinem");
        word(Cat.DIR, "north", "norden", "nord", "nördlich", "nordwärts");
        word(Cat.DIR, "south", "süden", "süd", "südlich", "südwärts");
        word(Cat.DIR, "east", "osten", "ost", "östlich", "ostwärts");
        word(Cat.DIR, "west", "westen", "west", "westlich", "westwärts");
        word(Cat.DIR, "north-east", "nordosten", "nordost", "nordöstlich");
        word(Cat.DIR, "north-west", "nordwesten", "nordwest", "nordwestlich");
        word(Cat.DIR, "south-east", "südosten", "südost", "südöstlich");
        word(Cat.DIR, "south-west", "südwesten", "südwest", "südwestlich");
        word(Cat.SIDE, "left", "links", "linkshin");
        word(Cat.SIDE, "right", "rechts");
        word(Cat.SIDE, "forward", "vorwärts", "vorne", "vor");
        word(Cat.SIDE, "straight", "geradeaus");
        word(Cat.SIDE, "backward", "rückwärts");
        word(Cat.UNIT, "degree", "grad");
        word(Cat.UNIT, "metre", "meter", "metern", "m", "schritt", "schritte", "schritten");
        word(Cat.UNIT, "second", "sekunde", "sekunden", "sek");
        word(Cat.UNIT, "minute", "minute", "minuten", "min");
        word(Cat.UNIT, "hour", "stunde", "stunden");
        word(Cat.UNIT, "moment", "moment", "augenblick", "kurz");
        word(Cat.UNIT, "while", "weile");
        word(Cat.UNIT, "bit", "bisschen", "bißchen", "stück", "wenig");
        word(Cat.UNIT, "twice", "zweimal");
        word(Cat.RULE, "rule", "regel", "regeln", "verbot", "verbote", "einschränkung", "einschränkungen");
        word(Cat.ONLY, "only", "nur", "ausschließlich", "lediglich", "bloß");
        word(Cat.AGAIN, "again", "wieder", "erneut", "wiederum");
        word(Cat.LASTING, "lasting", "immer", "fortan", "künftig", "zukünftig");
        word(Cat.COND, "when", "wenn", "falls", "sobald", "sofern");
    }

    private void functionWords() {
        word(Cat.PREP, "to", "zu", "nach", "hin", "richtung");
        word(Cat.PREP, "on", "auf");
        word(Cat.PREP, "in", "in", "innerhalb");
        word(Cat.PREP, "under", "unter", "unterhalb");
        word(Cat.PREP, "near", "neben", "nahe", "bei", "entlang");
        word(Cat.PREP, "at", "an");
        word(Cat.PREP, "beyond", "hinter", "jenseits");
        word(Cat.PREP, "from", "von", "aus");
        word(Cat.PREP, "around", "um", "herum", "umher");
        word(Cat.PREP, "over", "über");
        word(Cat.PREP, "through", "durch");
        word(Cat.PREP, "back", "zurück");
        word(Cat.PREP, "after", "hinterher");
        word(Cat.PREP, "away", "fern", "weg");
        word(Cat.PREP, "with", "mit");
        word(Cat.PREP, "for", "für");
        word(Cat.PREP, "until", "bis");
        word(Cat.PREP, "this-side", "diesseits");
        word(Cat.HERE, "here", "hier", "her", "hierher", "hierhin");
        word(Cat.HERE, "there", "da", "dort", "dorthin", "dahin");
        word(Cat.PRON, "it", "es", "sie");
        word(Cat.PRON, "him", "ihn", "ihm");
        word(Cat.ME, "me", "mir", "mich", "uns");
        word(Cat.CONN, "and", "und", "sowie");
        word(Cat.CONN, "then", "dann", "danach", "anschließend", "später", "zuletzt", "schließlich");
        word(Cat.NEG, "not", "nicht", "nie", "niemals", "kein", "keine", "keinen", "keiner", "keines", "keinem");
    }

    private void fillers() {
        for (String filler : List.of("bitte", "danke", "mal", "doch", "jetzt", "schnell", "langsam", "vorsichtig",
                "einfach", "ruhig", "sofort", "gleich", "auch", "ja", "nein", "hallo", "hey", "hi", "ok", "okay", "du",
                "dich", "dir", "ich", "ist", "sind", "bist", "hast", "hat", "habe", "liegt", "liegen", "liegenden",
                "hängt", "hängen", "steht", "stehen", "stehenden", "entfernt", "gelegen", "rote", "roten", "gelbe",
                "gelben", "reife", "reifen", "leckere", "leckeren", "schöne", "schönen", "frische", "frischen",
                "erste", "ersten", "erst", "zuerst", "zunächst", "also", "nun", "genau", "eigentlich", "kannst",
                "könntest", "würdest", "willst", "magst", "sollst", "darfst", "kann", "könnte", "würde", "sei",
                "lieb", "freundlich", "nett", "schön", "wohl", "gern", "gerne", "bitteschön", "dankeschön", "kumpel",
                "freund", "alter", "na", "so", "los", "gerade", "denn", "mehr")) {
            if (!words.containsKey(plain(filler))) {
                put(filler, Cat.FILLER, filler, false);
            }
        }
    }

    private void sayings() {
        // contractions are split before the words are read: zum is zu dem, ins in das
        phrase("zu dem", "to the");
        phrase("zu der", "to the");
        phrase("in der nähe des", "near the");
        phrase("in der nähe der", "near the");
        phrase("in der nähe von", "near");
        phrase("in die nähe des", "near the");
        phrase("in die nähe der", "near the");
        phrase("in die nähe von", "near");
        phrase("in der nähe", "near-me");
        phrase("in meiner nähe", "near-me");
        phrase("in deiner nähe", "near-me");
        phrase("neben dir", "near-me");
        phrase("bei dir", "near-me");
        phrase("um dich herum", "near-me");
        phrase("links von dir", "on-left");
        phrase("rechts von dir", "on-right");
        phrase("vor dir", "in-front");
        phrase("hinter dir", "behind-me");
        phrase("zu deiner linken", "on-left");
        phrase("zu deiner rechten", "on-right");
        phrase("auf deiner linken seite", "on-left");
        phrase("auf deiner rechten seite", "on-right");
        phrase("von links", "leftmost");
        phrase("von rechts", "rightmost");
        phrase("ganz links", "leftmost");
        phrase("ganz rechts", "rightmost");
        phrase("am nächsten", "nearest");
        phrase("am weitesten", "farthest");
        phrase("am höchsten", "highest");
        phrase("am niedrigsten", "lowest");
        phrase("an dem nächsten", "nearest");
        phrase("an dem weitesten", "farthest");
        phrase("an dem höchsten", "highest");
        phrase("an dem niedrigsten", "lowest");
        phrase("auf dem boden", "on-ground");
        phrase("von dem boden", "on-ground");
        phrase("vom boden", "on-ground");
        phrase("auf der erde", "on-ground");
        for (String far : List.of("auf der anderen seite", "auf die andere seite", "an das andere ufer",
                "auf das andere ufer", "am anderen ufer", "an dem anderen ufer", "ans andere ufer")) {
            phrase(far + " des", far.startsWith("auf die") || far.startsWith("an das") || far.startsWith("auf das")
                    || far.startsWith("ans") ? "to beyond the" : "beyond the");
            phrase(far + " der", far.startsWith("auf die") || far.startsWith("an das") || far.startsWith("auf das")
                    || far.startsWith("ans") ? "to beyond the" : "beyond the");
            phrase(far + " von", "beyond");
            phrase(far, far.startsWith("auf die") || far.startsWith("an das") || far.startsWith("auf das")
                    || far.startsWith("ans") ? "to beyond" : "beyond");
        }
        for (String near : List.of("auf dieser seite", "auf unserer seite", "auf dieser seite von", "diesseits von")) {
            phrase(near + " des", "this-side the");
            phrase(near + " der", "this-side the");
            phrase(near, "this-side");
        }
        phrase("diesseits des", "this-side the");
        phrase("jenseits des", "beyond the");
        for (String[] direction : new String[][] {{"nördlich", "north"}, {"südlich", "south"}, {"östlich", "east"},
            {"westlich", "west"}, {"nordöstlich", "northeast"}, {"nordwestlich", "northwest"},
            {"südöstlich", "southeast"}, {"südwestlich", "southwest"}}) {
            phrase(direction[0] + " von", direction[1] + " of");
            phrase(direction[0] + " des", direction[1] + " of the");
            phrase(direction[0] + " der", direction[1] + " of the");
            phrase("im " + direction[1].replace("north", "nord").replace("south", "süd").replace("east", "ost")
                    .replace("west", "west") + "en von", direction[1] + " of");
        }
        phrase("nach vorne", "forward");
        phrase("nach vorn", "forward");
        phrase("nach hinten", "backward");
        phrase("einen schritt zurück", "backward");
        phrase("ein paar schritte zurück", "backward");
        phrase("mach einen schritt zurück", "go backward");
        phrase("mach einen schritt vorwärts", "go forward");
        phrase("mach einen schritt nach vorne", "go forward");
        phrase("tritt zurück", "go backward");
        phrase("geh weiter", "carry-on");
        phrase("mach weiter", "carry-on");
        phrase("mach einfach weiter", "carry-on");
        phrase("mach was du willst", "carry-on");
        phrase("tu was du willst", "carry-on");
        phrase("mach dein ding", "carry-on");
        phrase("mach allein weiter", "carry-on");
        phrase("du bist frei", "carry-on");
        phrase("bleib stehen", "stop");
        phrase("halt an", "stop");
        phrase("halte an", "stop");
        phrase("hör auf", "stop");
        phrase("hor auf", "stop");
        put("halt", Cat.VERB, "stop", false);
        phrase("rühr dich nicht", "wait");
        phrase("beweg dich nicht", "wait");
        phrase("bleib wo du bist", "wait here");
        phrase("bleib hier", "wait here");
        phrase("sieh dich um", "explore");
        phrase("schau dich um", "explore");
        phrase("guck dich um", "explore");
        phrase("sieh dich in der gegend um", "explore");
        phrase("schau dich in der gegend um", "explore");
        phrase("such nach", "find");
        phrase("suche nach", "find");
        phrase("halt ausschau nach", "find");
        phrase("halte ausschau nach", "find");
        phrase("geh mit", "follow");
        phrase("komm mit", "follow");
        phrase("geh hinterher", "follow");
        phrase("lauf hinterher", "follow");
        phrase("hol mir", "fetch me");
        phrase("bring mir", "fetch me");
        phrase("gib mir", "fetch me");
        phrase("ich will", "fetch");
        phrase("ich möchte", "fetch");
        phrase("ein paar", "3");
        phrase("ein bisschen", "bit");
        phrase("ein wenig", "bit");
        phrase("ein stück", "bit");
        phrase("eine weile", "while");
        phrase("einen moment", "moment");
        phrase("alle früchte", "all fruit");
        phrase("und dann", "then");
        phrase("und danach", "then");
        phrase("nach hause", "home");
        phrase("wo du angefangen hast", "start-point");
        phrase("wo du gestartet bist", "start-point");
        phrase("wo du losgegangen bist", "start-point");
        phrase("dorthin zurück wo du angefangen hast", "back to start-point");
        phrase("zu deinem startpunkt", "to start-point");
        phrase("zu deinem ausgangspunkt", "to start-point");
        phrase("zum start", "to start-point");
        phrase("wo du warst", "home");
        phrase("sei so lieb und", "");
        phrase("sei so nett und", "");
        phrase("sei so gut und", "");
        phrase("wenn du kannst", "");
        phrase("wenn es geht", "");
        phrase("wenn möglich", "");
        phrase("vielen dank", "");
        phrase("danke schön", "");
        phrase("in ruhe", "");
        phrase("ab jetzt", "lasting");
        phrase("von jetzt an", "lasting");
        phrase("ab sofort", "lasting");
        phrase("von nun an", "lasting");
        phrase("ab nun", "lasting");
        phrase("für den rest des spiels", "lasting");
        phrase("bis zum ende des spiels", "lasting");
        phrase("nicht mehr", "not lasting");
        phrase("keine mehr", "not lasting");
        phrase("nur noch", "only");
        phrase("nichts außer", "only");
        phrase("du darfst", "permit");
        phrase("du kannst wieder", "permit again");
        phrase("darfst du", "permit");
        phrase("es ist erlaubt", "permit");
        phrase("immer wenn", "when");
        phrase("jedes mal wenn", "when");
        phrase("jedesmal wenn", "when");
    }

    // ---- building -------------------------------------------------------------------------------

    private void verb(String lemma, String... forms) {
        for (String form : forms) {
            putIfAbsent(form, Cat.VERB, lemma);
        }
    }

    /** A noun's forms: the singular ones and the plural ones, each a list separated by spaces. */
    private void noun(String lemma, String singular, String plural) {
        for (String form : singular.split(" ")) {
            put(form, Cat.NOUN, lemma, false);
        }
        for (String form : plural.split(" ")) {
            put(form, Cat.NOUN, lemma, true);
        }
    }

    private void word(Cat cat, String lemma, String... forms) {
        for (String form : forms) {
            putIfAbsent(form, cat, lemma);
        }
    }

    private void putIfAbsent(String word, Cat cat, String lemma) {
        for (String spelt : spellings(word)) {
            words.putIfAbsent(spelt, new Lexicon.Entry(cat, lemma, false));
        }
    }

    private void put(String word, Cat cat, String lemma, boolean plural) {
        for (String spelt : spellings(word)) {
            words.putIfAbsent(spelt, new Lexicon.Entry(cat, lemma, plural));
        }
    }

    private void phrase(String pattern, String replacement) {
        List<String> meaning = replacement.isEmpty() ? List.of() : List.of(replacement.split(" "));
        for (String spelt : spellings(pattern)) {
            phrases.putIfAbsent(spelt, meaning);
        }
    }

    /** A word as the tokenizer writes it (lower case, no accents), and as it is typed without umlauts and ß. */
    static List<String> spellings(String word) {
        String stripped = word.replace('ä', 'a').replace('ö', 'o').replace('ü', 'u');
        String transcribed = word.replace("ä", "ae").replace("ö", "oe").replace("ü", "ue");
        List<String> all = new ArrayList<>();
        for (String form : List.of(stripped, stripped.replace("ß", "ss"), transcribed.replace("ß", "ss"),
                transcribed)) {
            if (!all.contains(form)) {
                all.add(form);
            }
        }
        return all;
    }

    /** A word as the tokenizer writes it. */
    static String plain(String word) {
        return spellings(word).get(0);
    }
}
