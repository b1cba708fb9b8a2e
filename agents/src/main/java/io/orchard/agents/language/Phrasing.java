package io.orchard.agents.language;

/**
 * References and places in words, in a language the agents speak, for what an agent says about them
 * as it carries an instruction out: "the nearest banana that lies on a table", in German "die nächste
 * Banane, die auf einem Tisch liegt", "der nächsten Banane" in the dative.
 */
public final class Phrasing {

    /** The grammatical case a German noun phrase is in; English has none to speak of. */
    public enum Case {
        /** The subject: "der Baum". */
        NOMINATIVE,
        /** The object: "den Baum". */
        ACCUSATIVE,
        /** After "zu", "bei", "mit": "dem Baum". */
        DATIVE,
        /** Of something: "des Baumes". */
        GENITIVE
    }

    private Phrasing() {
    }

    /** A compass sector ("north-east", as the wire names it) as a noun: "north-east", "Nordosten". */
    public static String compass(String sector, Language language) {
        return language == Language.GERMAN ? GermanRestatement.compass(sector) : sector;
    }

    /** A compass sector as an adverb of place: "north-east", "nordöstlich". */
    public static String compassAdverb(String sector, Language language) {
        return language == Language.GERMAN ? GermanRestatement.adverb(sector) : sector;
    }

    /** One object of the reference, with its article: "a tree", "the castle"; in German, in the case given. */
    public static String noun(Reference reference, Language language, Case grammatical) {
        return language == Language.GERMAN ? GermanRestatement.noun(reference, german(grammatical))
                : Restatement.noun(reference);
    }

    /**
     * Every object of the reference, without an article: "coconuts that lie on a table", in German
     * "Kokosnüsse, die auf einem Tisch liegen".
     */
    public static String plural(Reference reference, Language language, Case grammatical) {
        return language == Language.GERMAN ? GermanRestatement.many(reference, german(grammatical))
                : Restatement.many(reference);
    }

    /** Where going to an area leads: "near the castle", in German "in die Nähe des Schlosses". */
    public static String where(Reference area, Language language) {
        return language == Language.GERMAN ? GermanRestatement.where(area) : Restatement.where(area);
    }

    private static GermanRestatement.Case german(Case grammatical) {
        return GermanRestatement.Case.values()[grammatical.ordinal()];
    }
}
