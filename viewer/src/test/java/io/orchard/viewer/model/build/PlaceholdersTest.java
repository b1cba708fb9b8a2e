package io.orchard.viewer.model.build;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class PlaceholdersTest {

    @Test
    void placeholderColourDependsOnlyOnTheName() {
        assertThat(Placeholders.colorFor("Guppy")).isEqualTo(Placeholders.colorFor("Guppy"));
        assertThat(Placeholders.colorFor("Guppy")).isNotEqualTo(
                Placeholders.colorFor("Bunny"));
    }
}
