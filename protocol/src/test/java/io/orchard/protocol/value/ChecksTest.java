package io.orchard.protocol.value;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.message.RegisterJointMessage;
import io.orchard.protocol.message.StartAnimationMessage;
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

    @ParameterizedTest
    @ValueSource(strings = {"Shoulder.L_CatArmature", "mixamorig:Hips", "Armature|Walk", "Left Knee", "clip#0",
        "node#12", "_rootJoint", "0", "Joint 1.001", "a123456789b123456789c123456789d123456789e123456789f123456789ghij"})
    void jointAndClipNamesAsModellingToolsWriteThemAreAccepted(String name) {
        assertThat(Checks.partName(name, "joint")).isEqualTo(name);
        assertThat(new StartAnimationMessage(3, "Guppy", name, true).timeSensor()).isEqualTo(name);
    }

    @ParameterizedTest
    @ValueSource(strings = {"", " Knee", "Knee ", "Kn\u0007ee", "Kn\"ee", "Knie/Knöchel", ".hidden",
        "a123456789b123456789c123456789d123456789e123456789f123456789ghijk"})
    void otherPartNamesAreRefusedNamingTheFieldAndTheValue(String name) {
        assertThatThrownBy(() -> new RegisterJointMessage(3, "Guppy", name)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageStartingWith("joint must be 1 to 64 characters");
    }

    @Test
    void agentNamesKeepTheirShorterRule() {
        assertThatThrownBy(() -> Checks.name("Shoulder.L", "agent")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageStartingWith("agent must be a letter followed by up to 31");
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
