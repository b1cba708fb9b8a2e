package io.orchard.protocol;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.value.Nullable;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import tools.jackson.core.JacksonException;
import tools.jackson.core.StreamReadConstraints;
import tools.jackson.core.exc.StreamConstraintsException;
import tools.jackson.databind.json.JsonMapper;

class StrictJsonTest {

    record Tree(String name, int height, @Nullable String note) {}

    private final JsonMapper mapper = StrictJson.builder().build();

    @Test
    void aWellFormedRecordIsRead() {
        assertThat(mapper.readValue("{\"name\":\"oak\",\"height\":12}", Tree.class))
                .isEqualTo(new Tree("oak", 12, null));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        unknown field                | {"name":"oak","height":12,"hieght":3}
        missing component            | {"name":"oak"}
        null for a number            | {"name":"oak","height":null}
        duplicate key                | {"name":"oak","height":12,"height":13}
        something after the document | {"name":"oak","height":12} {}
        fraction for an integer      | {"name":"oak","height":12.5}
        string for a number          | {"name":"oak","height":"12"}
        number for a string          | {"name":7,"height":12}
        comment                      | {"name":"oak",/* tall */"height":12}
        """)
    void whatIsNotStrictlyTheRecordIsRefused(String what, String json) {
        assertThatThrownBy(() -> mapper.readValue(json, Tree.class)).isInstanceOf(JacksonException.class);
    }

    @Test
    void writingKeepsTheComponentsInOrderAndLeavesOutNulls() {
        assertThat(mapper.writeValueAsString(new Tree("oak", 12, null))).isEqualTo("{\"name\":\"oak\",\"height\":12}");
    }

    @Test
    void nestingBeyondTheGivenDepthIsRefusedNamingTheLimit() {
        JsonMapper shallow = StrictJson.builder(StreamReadConstraints.builder().maxNestingDepth(3).build()).build();

        assertThat(shallow.readTree("[[[1]]]").get(0).get(0).get(0).asInt()).isEqualTo(1);
        assertThatThrownBy(() -> shallow.readTree("[[[[1]]]]"))
                .isInstanceOf(StreamConstraintsException.class)
                .hasMessageContaining("nesting depth (4) exceeds the maximum allowed (3");
    }

    @Test
    void aStringLongerThanTheGivenLengthIsRefusedNamingTheLimit() {
        JsonMapper terse = StrictJson.builder(StreamReadConstraints.builder().maxStringLength(10).build()).build();

        assertThatThrownBy(() -> terse.readTree("[\"" + "x".repeat(11) + "\"]"))
                .isInstanceOf(StreamConstraintsException.class)
                .hasMessageContaining("String value length (11) exceeds the maximum allowed (10");
    }
}
