package io.orchard.agents.errand;

import io.orchard.agents.language.Reference;

/** Small pieces of the agent's answers. */
final class Restated {

    private Restated() {}

    /** A reference without its article: "coconut that lies on a table", "Roadrunner". */
    static String bare(Reference reference) {
        String words = reference.words();
        for (String article : new String[] {"a ", "an ", "the "}) {
            if (words.startsWith(article)) {
                return words.substring(article.length());
            }
        }
        return words;
    }

    /** A known thing in words: "the tree T3", "the castle", "Guppy". */
    static String thing(Known known) {
        return switch (known.kind()) {
            case AGENT -> known.id();
            case CASTLE, RIVER, FOREST -> "the " + known.kind().wireName();
            case START -> "where I started";
            default -> "the " + known.kind().wireName() + " " + known.id();
        };
    }
}
