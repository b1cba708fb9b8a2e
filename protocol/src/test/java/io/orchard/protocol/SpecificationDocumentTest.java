package io.orchard.protocol;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** docs/protocol.md as a reader finds it: sections in the order of their numbers, and example lines that decode. */
class SpecificationDocumentTest {

    private static final Pattern HEADING = Pattern.compile("^(#{2,3}) (\\d+)\\.(\\d+)?\\.? ");

    private static List<String> lines;

    @BeforeAll
    static void read() throws IOException {
        lines = Files.readAllLines(Paths.get("../docs/protocol.md"), StandardCharsets.UTF_8);
    }

    @Test
    void sectionsComeInTheOrderOfTheirNumbers() {
        List<String> found = new ArrayList<>();
        int section = 0;
        int subsection = 0;
        for (String line : lines) {
            Matcher heading = HEADING.matcher(line);
            if (!heading.find()) {
                continue;
            }
            found.add(line);
            int number = Integer.parseInt(heading.group(2));
            if (heading.group(1).length() == 2) {
                assertThat(number).as("after section %d: %s", section, line).isEqualTo(section + 1);
                section = number;
                subsection = 0;
            } else {
                int sub = Integer.parseInt(heading.group(3));
                assertThat(List.of(number, sub)).as("after %d.%d: %s", section, subsection, line)
                        .containsExactly(section, subsection + 1);
                subsection = sub;
            }
        }
        assertThat(found).as("numbered headings").hasSizeGreaterThan(30);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("exampleLines")
    void everyExampleLineDecodes(String where, String line) {
        assertThat(new MessageCodec().decode(line)).as(where).isNotNull();
    }

    /** The lines of the ```json blocks and the C: and S: lines of the example session. */
    static Stream<org.junit.jupiter.params.provider.Arguments> exampleLines() throws IOException {
        read();
        List<org.junit.jupiter.params.provider.Arguments> examples = new ArrayList<>();
        boolean inJson = false;
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.equals("```json")) {
                inJson = true;
            } else if (line.equals("```")) {
                inJson = false;
            } else if (inJson && line.startsWith("{")) {
                examples.add(org.junit.jupiter.params.provider.Arguments.of("line " + (i + 1), line));
            } else if (line.startsWith("C: {") || line.startsWith("S: {")) {
                examples.add(org.junit.jupiter.params.provider.Arguments.of("line " + (i + 1), line.substring(3)));
            }
        }
        assertThat(examples).hasSizeGreaterThan(50);
        return examples.stream();
    }
}
