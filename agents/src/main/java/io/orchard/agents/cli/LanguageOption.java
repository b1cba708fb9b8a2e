package io.orchard.agents.cli;

import io.orchard.agents.AgentController;
import io.orchard.agents.language.Language;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code --language CODE}, as a picocli mixin for {@code agent}, {@code agents} and {@code parse}:
 * the language the agents understand besides English, and answer a sentence in when it is in it.
 */
public final class LanguageOption {

    /** Options from the command line only. */
    public LanguageOption() {
    }

    @Option(names = "--language", paramLabel = "CODE", defaultValue = "en",
            description = "The language the agents understand besides English, and answer in when spoken to in it: "
                    + "en (English only) or de (German too) (default: ${DEFAULT-VALUE})")
    private String code;

    @Spec(Spec.Target.MIXEE)
    private CommandSpec spec;

    /**
     * The language the option names.
     *
     * @throws ParameterException when it names none, naming the value and what was expected
     */
    public Language language() {
        Language language = Language.of(code);
        if (language == null) {
            throw new ParameterException(spec.commandLine(), "invalid value for option '--language': '" + code
                    + "' (expected en or de)");
        }
        return language;
    }

    /** Has {@code agent} understand the language, when it is not English. */
    void apply(AgentController agent) {
        agent.understand(language());
    }
}
