package io.orchard.agents.language;

import io.orchard.protocol.value.Nullable;
import java.util.Locale;

/**
 * A language the agents understand and answer in. English is every agent's; German is a second
 * language an agent can be given ({@code --language de}, {@code AgentController.understand}): it then
 * reads each sentence in the language the sentence is in, and answers in that language. The goals
 * are the same in both: German is a second way of saying them.
 */
public enum Language {
    /** English: every agent understands it. */
    ENGLISH("en", "English"),
    /** German: "geh zum Schloss", "nimm die nächste Banane", "was siehst du?". */
    GERMAN("de", "German");

    private final String code;
    private final String englishName;

    Language(String code, String englishName) {
        this.code = code;
        this.englishName = englishName;
    }

    /** The language's ISO 639-1 code, as {@code --language} takes it: {@code en}, {@code de}. */
    public String code() {
        return code;
    }

    /** The language's name in English: "English", "German". */
    public String englishName() {
        return englishName;
    }

    /** The language of this code or name ("de", "german", "Deutsch"), ignoring case; null when none. */
    public static @Nullable Language of(String codeOrName) {
        if (codeOrName == null) {
            return null;
        }
        String wanted = codeOrName.strip().toLowerCase(Locale.ROOT);
        for (Language language : values()) {
            if (language.code.equals(wanted) || language.englishName.toLowerCase(Locale.ROOT).equals(wanted)) {
                return language;
            }
        }
        return wanted.equals("deutsch") ? GERMAN : null;
    }
}
