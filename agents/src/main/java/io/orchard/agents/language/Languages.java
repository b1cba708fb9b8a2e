package io.orchard.agents.language;

import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Tells a sentence in another language from English that was not understood, by the words of
 * other languages it is made of ("nimm bitte die Banane", "prends la banane"), so that the answer
 * can say, in English, which language the agents understand. Only words that are not English are
 * counted, and only a sentence that the grammar did not understand is looked at, so an English
 * instruction is never taken for another language.
 */
final class Languages {

    private static final Map<String, Set<String>> MARKERS = Map.of(
            "German", Set.of("nimm", "nehme", "bitte", "die", "der", "das", "dem", "den", "geh", "gehe", "zum", "zur",
                    "hol", "hole", "mir", "mich", "eine", "einen", "ein", "bist", "du", "wo", "was", "ist", "und",
                    "nicht", "sammle", "sammel", "pflucke", "banane", "bananen", "kokosnuss", "kokosnusse", "tomate",
                    "tomaten", "schloss", "burg", "fluss", "brucke", "baum", "tisch", "links", "rechts", "norden",
                    "suden", "osten", "westen", "ich", "wie", "viele", "hast", "siehst", "warum", "lauf", "laufe",
                    "dreh", "drehe", "dich", "zu", "uber", "halt", "folge", "finde", "suche", "alle", "zuruck"),
            "French", Set.of("prends", "prend", "prenez", "la", "le", "les", "va", "vas", "allez", "au", "aux", "des",
                    "une", "et", "est", "banane", "noix", "chateau", "riviere", "pont", "arbre", "ramasse", "mange",
                    "cherche", "suis", "moi", "tu", "vous", "plait", "tourne", "gauche", "droite", "ou", "es"),
            "Spanish", Set.of("ve", "al", "el", "la", "los", "las", "coge", "toma", "recoge", "castillo", "rio", "puente",
                    "arbol", "platano", "por", "favor", "donde", "estas", "una", "y", "gira", "izquierda",
                    "derecha", "busca", "sigue"),
            "Italian", Set.of("raccogli", "prendi", "vai", "il", "lo", "la", "gli", "della", "castello", "fiume", "ponte",
                    "albero", "tavolo", "per", "favore", "dove", "sei", "gira", "sinistra", "destra", "cerca", "segui"),
            "Dutch", Set.of("pak", "de", "het", "een", "ga", "naar", "kasteel", "rivier", "brug", "boom", "tafel",
                    "banaan", "kokosnoot", "alsjeblieft", "waar", "ben", "je", "pluk", "volg", "zoek", "links",
                    "rechts"));

    private Languages() {
    }

    /**
     * The language these words most look like, when it is not English: at least two of them, and
     * at least half, are words of that language that English does not have; null otherwise, and
     * "another language" when two languages fit as well.
     */
    static String other(List<Tokenizer.Token> tokens) {
        return other(tokens, List.of(Language.ENGLISH));
    }

    /** As {@link #other(List)}, for an interpreter that understands these languages: never one of them. */
    static String other(List<Tokenizer.Token> tokens, List<Language> understood) {
        List<String> words = tokens.stream().filter(Tokenizer.Token::isWord).map(Tokenizer.Token::text).toList();
        String best = null;
        int most = 0;
        boolean tie = false;
        for (Map.Entry<String, Set<String>> language : MARKERS.entrySet()) {
            if (understood.stream().anyMatch(known -> known.englishName().equals(language.getKey()))) {
                continue;
            }
            int count = (int) words.stream().filter(language.getValue()::contains).count();
            if (count > most) {
                best = language.getKey();
                most = count;
                tie = false;
            } else if (count == most && count > 0) {
                tie = true;
            }
        }
        if (most < 2 || 2 * most < words.size()) {
            return null;
        }
        return tie ? "another language" : best;
    }
}
