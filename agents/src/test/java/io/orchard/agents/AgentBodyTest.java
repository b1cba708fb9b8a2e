package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class AgentBodyTest {

    @Test
    void theDefaultsMakeAWorkingBody() {
        AgentBody body = AgentBody.builder().build();

        assertThat(body.body().radius()).isEqualTo(0.5);
        assertThat(body.body().gripper().reach()).isEqualTo(0.6);
        assertThat(body.model()).isNull();
        assertThat(body.perceptionEvery()).isEqualTo(1);
    }

    @Test
    void theAnimationsAreAmongTheTimeSensorsRegistered() {
        AgentBody body = AgentBody.builder().timeSensors("PippinTSJump").walkAnimation("PippinTSWalk")
                .graspAnimation("PippinTSGrasp").build();

        assertThat(body.timeSensors()).containsExactly("PippinTSJump", "PippinTSWalk", "PippinTSGrasp");
        assertThat(body.walkAnimation()).isEqualTo("PippinTSWalk");
    }

    @Test
    void badValuesAreNamedWithWhatWasExpected() {
        assertThatThrownBy(() -> AgentBody.builder().radius(-1)).hasMessage("radius must be greater than 0, was -1.0");
        assertThatThrownBy(() -> AgentBody.builder().gripper("hands", 0.6, 1.5, 1.0))
                .hasMessage("gripper maxHeight must not be below minHeight (1.5), was 1.0");
        assertThatThrownBy(() -> AgentBody.builder().sight(40, 7)).hasMessageContaining("at most 2*pi radians, was 7.0");
        assertThatThrownBy(() -> AgentBody.builder().joints("Left Knee ")).hasMessageContaining("joint must be 1 to 64 characters");
        assertThatThrownBy(() -> AgentBody.builder().model("pippin.obj")).hasMessageContaining("unknown extension");
        assertThatThrownBy(() -> AgentBody.builder().perceptionEvery(0))
                .hasMessage("perceptionEvery must be at least 1 tick, was 0");
    }
}
