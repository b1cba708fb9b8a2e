package io.orchard.viewer.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class ModelLimitsTest {

    @Test
    void defaultsAreThoseDocumented() {
        assertThat(ModelLimits.DEFAULTS).isEqualTo(
                new ModelLimits(4 * 1024 * 1024, 20_000, 64, 1_000_000, 2048));
    }

    @Test
    void withersChangeOneLimit() {
        ModelLimits limits = ModelLimits.DEFAULTS.withMaxNodes(10).withMaxDepth(8)
                .withMaxInputBytes(100).withMaxArrayValues(50).withMaxTextureSize(16);

        assertThat(limits).isEqualTo(new ModelLimits(100, 10, 8, 50, 16));
    }

    @ParameterizedTest
    @ValueSource(ints = {0, -1})
    void nonPositiveLimitIsRefusedNamingIt(int value) {
        assertThatThrownBy(() -> ModelLimits.DEFAULTS.withMaxNodes(value))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("maxNodes must be positive: " + value);
    }

    @Test
    void depthAboveTheCeilingIsRefused() {
        assertThatThrownBy(() -> ModelLimits.DEFAULTS.withMaxDepth(ModelLimits.DEPTH_CEILING + 1))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("maxDepth must be at most 256: 257");
    }
}
