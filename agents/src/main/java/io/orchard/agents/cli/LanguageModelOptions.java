package io.orchard.agents.cli;

import io.orchard.agents.AgentController;
import io.orchard.agents.language.LanguageModel;
import java.net.URI;
import java.net.URISyntaxException;
import java.time.Duration;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * The language model that {@code agent}, {@code agents} and {@code parse} may consult, as a picocli
 * mixin: {@code --language-model URL}, {@code --language-model-name MODEL} and
 * {@code --language-model-timeout SECONDS}; none unless named.
 */
public final class LanguageModelOptions {

    /** Options from the command line only. */
    public LanguageModelOptions() {
    }

    @Option(names = "--language-model", paramLabel = "URL",
            description = "Ask the language model served at URL (an OpenAI-compatible API, such as "
                    + "http://localhost:11434/v1 for Ollama or http://localhost:8080/v1 for llama.cpp's server) for "
                    + "the instructions the agents' grammar does not understand; off unless given")
    private String url;

    @Option(names = "--language-model-name", paramLabel = "MODEL",
            description = "The model to ask, as that server names it (needed with --language-model)")
    private String model;

    @Option(names = "--language-model-timeout", paramLabel = "SECONDS", defaultValue = "10",
            description = "How long to wait for the model's answer (default: ${DEFAULT-VALUE})")
    private double timeoutSeconds;

    @Spec(Spec.Target.MIXEE)
    private CommandSpec spec;

    /**
     * The model the options name; null when none is.
     *
     * @throws ParameterException when the options are incomplete or a value is bad, naming it
     */
    public LanguageModel model() {
        if (url == null) {
            if (model != null) {
                throw new ParameterException(spec.commandLine(), "--language-model-name needs --language-model URL");
            }
            return null;
        }
        if (model == null) {
            throw new ParameterException(spec.commandLine(),
                    "--language-model needs --language-model-name MODEL, the model to ask");
        }
        if (!(timeoutSeconds > 0) || timeoutSeconds > 600) {
            throw new ParameterException(spec.commandLine(), "invalid value for option '--language-model-timeout': '"
                    + timeoutSeconds + "' (expected seconds, more than 0 and at most 600)");
        }
        try {
            return new LanguageModel(new URI(url), model, Duration.ofMillis(Math.round(timeoutSeconds * 1000)));
        } catch (URISyntaxException | IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), "invalid value for option '--language-model': '" + url
                    + "' (expected an http or https address such as http://localhost:11434/v1)");
        }
    }

    /** Has {@code agent} consult the model, when one is named. */
    void apply(AgentController agent) {
        LanguageModel languageModel = model();
        if (languageModel != null) {
            agent.consultLanguageModel(languageModel);
        }
    }
}
