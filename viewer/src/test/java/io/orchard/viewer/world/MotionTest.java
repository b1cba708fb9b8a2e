package io.orchard.viewer.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.value.Vec3;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class MotionTest {

    private final Motion move = new Motion(new Vec3(0, 0, 0), new Vec3(8, 0, -4), 10, 2);

    @ParameterizedTest(name = "at {0} s the walk is {1} done")
    @CsvSource({"9, 0", "10, 0", "10.5, 0.25", "11, 0.5", "12, 1", "30, 1"})
    void fractionIsClampedToTheWalk(double time, double fraction) {
        assertThat(move.fractionAt(time)).isEqualTo(fraction);
    }

    @Test
    void positionFollowsTheFraction() {
        assertThat(move.at(11)).isEqualTo(new Vec3(4, 0, -2));
        assertThat(move.endTime()).isEqualTo(12);
    }

    @Test
    void aWalkOfNoDurationJumpsAtItsStart() {
        Motion jump = new Motion(new Vec3(0, 0, 0), new Vec3(1, 0, 1), 5, 0);
        assertThat(jump.at(4.99)).isEqualTo(new Vec3(0, 0, 0));
        assertThat(jump.at(5)).isEqualTo(new Vec3(1, 0, 1));
    }

    @Test
    void badDurationsAreRefusedWithTheValue() {
        assertThatThrownBy(() -> new Motion(new Vec3(0, 0, 0), new Vec3(1, 0, 1), 0, -1))
                .hasMessageContaining("duration must be zero or more seconds, was -1.0");
    }
}
