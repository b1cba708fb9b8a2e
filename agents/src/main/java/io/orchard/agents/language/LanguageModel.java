package io.orchard.agents.language;

import java.net.URI;
import java.time.Duration;
import java.util.Locale;
import java.util.Objects;

/**
 * Where a language model is served over an OpenAI-compatible HTTP API (llama.cpp's server,
 * Ollama, vLLM and others), for {@link LanguageModelInterpreter}.
 *
 * @param endpoint the API's base address, such as {@code http://localhost:11434/v1}; requests go to
 *                 its {@code /chat/completions}
 * @param model    the model's name as the server knows it, such as {@code llama3.2}
 * @param timeout  how long to wait for an answer before saying the sentence was not understood
 */
public record LanguageModel(URI endpoint, String model, Duration timeout) {

    /** How long an answer is waited for unless told otherwise. */
    public static final Duration DEFAULT_TIMEOUT = Duration.ofSeconds(10);

    /** Checks the components; a bad value is refused with an exception that names it. */
    public LanguageModel {
        Objects.requireNonNull(endpoint, "endpoint");
        Objects.requireNonNull(model, "model");
        Objects.requireNonNull(timeout, "timeout");
        String scheme = endpoint.getScheme() == null ? "" : endpoint.getScheme().toLowerCase(Locale.ROOT);
        if (!scheme.equals("http") && !scheme.equals("https") || endpoint.getHost() == null) {
            throw new IllegalArgumentException("endpoint must be an http or https address such as "
                    + "http://localhost:11434/v1, was '" + endpoint + "'");
        }
        if (model.isBlank()) {
            throw new IllegalArgumentException("model must name the model the server serves, was '" + model + "'");
        }
        if (timeout.isNegative() || timeout.isZero()) {
            throw new IllegalArgumentException("timeout must be more than 0, was " + timeout);
        }
    }

    /** The address chat completions are posted to. */
    URI completions() {
        String base = endpoint.toString();
        if (base.endsWith("/chat/completions")) {
            return endpoint;
        }
        return URI.create(base.endsWith("/") ? base + "chat/completions" : base + "/chat/completions");
    }
}
