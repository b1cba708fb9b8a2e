package io.orchard.viewer.model.gltf;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.ModelException.Kind;
import io.orchard.viewer.model.ModelLimits;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The JSON of a glTF document is read strictly and within the model's limits. */
class GltfJsonTest {

    private static final String ASSET = "{\"asset\": {\"version\": \"2.0\"}";

    @Test
    void aDocumentIsReadIntoATreeAfterAByteOrderMark() throws ModelException {
        assertThat(GltfJson.read("\uFEFF" + ASSET + ", \"nodes\": [{\"name\": \"Guppy\"}]}",
                ModelLimits.DEFAULTS).at("/nodes/0/name").stringValue()).isEqualTo("Guppy");
    }

    @Test
    void nestingDeeperThanTheModelsDepthLimitIsRefusedNamingTheLimit() throws ModelException {
        ModelLimits shallow = ModelLimits.DEFAULTS.withMaxDepth(3);

        assertThat(GltfJson.read(ASSET + ", \"extras\": [[1]]}", shallow)).isNotNull();
        assertThatThrownBy(() -> GltfJson.read(ASSET + ", \"extras\": [[[1]]]}", shallow))
                .isInstanceOf(ModelException.class)
                .hasMessage("glTF JSON is over a limit: Document nesting depth (4) exceeds the"
                        + " maximum allowed (3)")
                .satisfies(e -> assertThat(((ModelException) e).kind()).isEqualTo(Kind.TOO_LARGE));
    }

    @Test
    void aStringLongerThanTheInputLimitIsRefusedNamingTheLimit() {
        ModelLimits small = ModelLimits.DEFAULTS.withMaxInputBytes(1000);

        assertThatThrownBy(() -> GltfJson.read(ASSET + ", \"extras\": \"" + "x".repeat(1001)
                + "\"}", small))
                .isInstanceOf(ModelException.class)
                .hasMessageContaining("exceeds the maximum allowed (1000)")
                .satisfies(e -> assertThat(((ModelException) e).kind()).isEqualTo(Kind.TOO_LARGE));
    }

    @Test
    void aNumberLongerThanANumberNeedsIsRefusedNamingTheLimit() {
        String digits = "1".repeat(GltfJson.MAX_NUMBER_CHARS + 1);

        assertThatThrownBy(() -> GltfJson.read(ASSET + ", \"extras\": " + digits + "}",
                ModelLimits.DEFAULTS))
                .isInstanceOf(ModelException.class)
                .hasMessageContaining("Number value length (" + (GltfJson.MAX_NUMBER_CHARS + 1)
                        + ") exceeds the maximum allowed (" + GltfJson.MAX_NUMBER_CHARS + ")")
                .satisfies(e -> assertThat(((ModelException) e).kind()).isEqualTo(Kind.TOO_LARGE));
    }

    @Test
    void aNumberTooLargeForADoubleIsRefusedSayingWhereItIs() {
        assertThatThrownBy(() -> GltfJson.read(ASSET + ", \"nodes\": [{\"translation\":"
                + " [0, 1e999, 0]}]}", ModelLimits.DEFAULTS))
                .isInstanceOf(ModelException.class)
                .hasMessage("glTF JSON at /nodes/0/translation/1: number Infinity is out of range")
                .satisfies(e -> assertThat(((ModelException) e).kind()).isEqualTo(Kind.BAD_VALUE));
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '`', textBlock = """
        a duplicate key            | `{"asset": {"version": "2.0", "version": "1.0"}}`  | Duplicate Object property "version"
        something after it         | `{"asset": {"version": "2.0"}} {}`                  | Trailing token
        a comment                  | `{"asset": /* 2.0 */ {"version": "2.0"}}`          | at line 1, column 11
        a trailing comma           | `{"asset": {"version": "2.0"},}`                   | at line 1, column 30
        a truncated document       | `{"asset": {"version": "2.0"`                      | truncated
        """)
    void whatIsNotStrictJsonIsRefusedAsMalformed(String what, String json, String message) {
        assertThatThrownBy(() -> GltfJson.read(json, ModelLimits.DEFAULTS))
                .isInstanceOf(ModelException.class)
                .hasMessageStartingWith("glTF JSON")
                .hasMessageContaining(message)
                .satisfies(e -> assertThat(((ModelException) e).kind()).isEqualTo(Kind.MALFORMED));
    }
}
