package io.orchard.viewer.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import io.orchard.protocol.value.Vec3;
import org.junit.jupiter.api.Test;

class PickingTest {

    private static final Vec3 FEET = new Vec3(0, 0, -10);

    @Test
    void aRayThroughTheBodyHitsItsSide() {
        double hit = Picking.cylinderHit(0, 1, 0, 0, 0, -1, FEET, 0.5, 1.2);
        assertThat(hit).isCloseTo(9.5, within(1e-9));
    }

    @Test
    void aRayFromAboveHitsTheTop() {
        double hit = Picking.cylinderHit(0, 10, -10, 0, -1, 0, FEET, 0.5, 1.2);
        assertThat(hit).isCloseTo(8.8, within(1e-9));
    }

    @Test
    void raysBesideOrAboveMiss() {
        assertThat(Picking.cylinderHit(2, 1, 0, 0, 0, -1, FEET, 0.5, 1.2)).isInfinite();
        assertThat(Picking.cylinderHit(0, 3, 0, 0, 0, -1, FEET, 0.5, 1.2)).isInfinite();
        assertThat(Picking.cylinderHit(0, 1, 0, 0, 0, 1, FEET, 0.5, 1.2)).as("pointing away").isInfinite();
    }

    @Test
    void theNearestAgentIsPicked() {
        WorldMirror mirror = new WorldMirror();
        mirror.apply(WorldMirrorTest.snapshot(0));
        mirror.apply(WorldMirrorTest.added("Far", new Vec3(0, 0, -20), 0));
        mirror.apply(WorldMirrorTest.added("Near", new Vec3(0, 0, -10), 0));

        AgentView picked = Picking.pick(mirror.agents(), 0, 0, 1, 0, 0, 0, -1, 0.5);

        assertThat(picked.name()).isEqualTo("Near");
    }
}
