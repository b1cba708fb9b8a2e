package io.orchard.protocol.value;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class ChecksTest {

    @Test
    void theHandWrittenNameCheckAgreesWithThePattern() {
        Random random = new Random(17);
        String alphabet = "aZ9_-. é\u0001";
        for (int i = 0; i < 20_000; i++) {
            StringBuilder name = new StringBuilder();
            for (int k = random.nextInt(36); k > 0; k--) {
                name.append(alphabet.charAt(random.nextInt(alphabet.length())));
            }
            String candidate = name.toString();
            assertThat(Checks.isName(candidate)).as("'%s'", candidate)
                    .isEqualTo(Checks.NAME.matcher(candidate).matches());
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"", " ", "F\u0007", "a-very-long-identifier-that-goes-past-sixty-four-characters-without-end"})
    void badIdsAreRefusedNamingTheField(String id) {
        assertThatThrownBy(() -> Checks.id(id, "fruit")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageStartingWith("fruit must be");
    }

    @Test
    void sectorsFollowTheCompass() {
        assertThat(Sector.of(0, -1)).isEqualTo(Sector.NORTH);
        assertThat(Sector.of(1, -1)).isEqualTo(Sector.NORTH_EAST);
        assertThat(Sector.of(1, 0)).isEqualTo(Sector.EAST);
        assertThat(Sector.of(0, 1)).isEqualTo(Sector.SOUTH);
        assertThat(Sector.of(-1, 1)).isEqualTo(Sector.SOUTH_WEST);
        assertThat(Sector.of(-1, 0)).isEqualTo(Sector.WEST);
    }
}
