package io.orchard.server.world.scenario;

import io.orchard.protocol.StrictJson;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import tools.jackson.core.JacksonException;
import tools.jackson.core.json.JsonReadFeature;
import tools.jackson.core.util.DefaultIndenter;
import tools.jackson.core.util.DefaultPrettyPrinter;
import tools.jackson.core.util.Separators;
import tools.jackson.databind.ObjectWriter;
import tools.jackson.databind.SerializationFeature;
import tools.jackson.databind.json.JsonMapper;

/**
 * Reads and writes scenario files: UTF-8 JSON, one {@link Scenario} per file. Reading is strict,
 * because a scenario is written by hand: an unknown field (a typo), a missing field, a duplicate
 * key, a number that is not finite or a negative size is refused with a {@link ScenarioException}
 * naming the object, the problem and where it is in the file. Writing is indented, in the order of
 * the record's components, leaving out absent optional fields.
 *
 * <p>Reading checks the form of the file only; {@code World.fromScenario} checks that its things fit
 * together.
 *
 * <p>Thread-safe: the mapper is immutable.
 */
public final class ScenarioFile {

    private static final JsonMapper MAPPER = StrictJson.builder()
            // NaN and Infinity are read so that the record that holds one can say which number it is.
            .enable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS)
            .defaultPrettyPrinter(new DefaultPrettyPrinter()
                    .withSeparators(Separators.createDefaultInstance().withObjectNameValueSpacing(Separators.Spacing.AFTER))
                    .withArrayIndenter(DefaultIndenter.SYSTEM_LINEFEED_INSTANCE))
            .build();

    private static final ObjectWriter WRITER = MAPPER.writer(SerializationFeature.INDENT_OUTPUT);

    private ScenarioFile() {}

    /**
     * Reads a scenario file.
     *
     * @throws IOException       when the file cannot be read
     * @throws ScenarioException when it is not a well-formed scenario
     */
    public static Scenario read(Path file) throws IOException {
        return parse(Files.readString(file, StandardCharsets.UTF_8), file.getFileName().toString());
    }

    /**
     * Reads a scenario from JSON text.
     *
     * @param source what to call the text in messages, for example the file's name
     * @throws ScenarioException when it is not a well-formed scenario
     */
    public static Scenario parse(String json, String source) {
        try {
            return MAPPER.readValue(json, Scenario.class);
        } catch (JacksonException e) {
            throw new ScenarioException(source + ": " + JsonProblems.describe(e, json, MAPPER), e);
        }
    }

    /** Writes a scenario file, replacing the file if it exists. */
    public static void write(Scenario scenario, Path file) throws IOException {
        Files.writeString(file, toJson(scenario), StandardCharsets.UTF_8);
    }

    /** The scenario as indented JSON text, ending with a newline. */
    public static String toJson(Scenario scenario) {
        return WRITER.writeValueAsString(scenario) + "\n";
    }
}
