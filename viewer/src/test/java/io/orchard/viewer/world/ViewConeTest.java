package io.orchard.viewer.world;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.AgentState;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.CastleShape;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RiverShape;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** What an agent standing at the origin, facing north (-z), perceives, by the protocol's rules. */
class ViewConeTest {

    /** A castle 10 wide, 10 to 20 units east of the origin. */
    static final List<Point2> CASTLE = List.of(new Point2(10, -5), new Point2(20, -5), new Point2(20, 5),
            new Point2(10, 5));

    static Sight sight(double range, double fieldDegrees) {
        return new Sight(range, Math.toRadians(fieldDegrees));
    }

    @ParameterizedTest(name = "({0}, {1}) seen with range 30 and field {2} deg: {3}")
    @CsvSource({
            "0, -10, 90, true",     // straight ahead
            "0, -31, 90, false",    // beyond range
            "-9, -10, 90, true",    // 42 deg left, inside half the field
            "-11, -10, 90, false",  // 48 deg left, outside
            "0, 10, 90, false",     // behind
            "0, 10, 360, true",     // behind, but the agent sees all around
            "25, 0, 360, false",    // behind the castle
            "5, 0, 360, true",      // before the castle
            "20, -20, 360, true"    // past the castle's corner
    })
    void seesByRangeFieldAndCastle(double x, double z, double field, boolean seen) {
        assertThat(ViewCone.sees(CASTLE, new Vec3(0, 0, 0), 0, sight(30, field), x, z)).isEqualTo(seen);
    }

    @Test
    void aTurnedAgentLooksWhereItsHeadingPoints() {
        double west = Math.PI / 2;
        assertThat(ViewCone.sees(CASTLE, new Vec3(0, 0, 0), west, sight(30, 60), -10, 0)).isTrue();
        assertThat(ViewCone.sees(CASTLE, new Vec3(0, 0, 0), west, sight(30, 60), 0, -10)).isFalse();
    }

    @Test
    void sightingListsWhatTheAgentSeesNow() {
        WorldMirror mirror = new WorldMirror();
        mirror.apply(new WorldSnapshotMessage(0, 0, new Bounds(-50, -50, 50, 50),
                List.of(new Obstacle("T1", ObjectKind.TREE, new Point2(0, -8), 2, 6),
                        new Obstacle("D1", ObjectKind.TABLE, new Point2(0, 8), 1, 1)),
                new CastleShape(CASTLE, 8),
                new RiverShape(List.of(new Point2(-50, 30), new Point2(50, 30), new Point2(50, 35), new Point2(-50, 35))),
                List.of(), List.of(new FruitState("F1", FruitKind.BANANA, new Vec3(2, 0.25, -5), null),
                        new FruitState("F2", FruitKind.TOMATO, new Vec3(30, 0.15, 0), null)), List.of()));
        Body body = new Body(0.5, 1.2, 8, new Gripper("hands", 0.6, 0, 1.5), sight(40, 180));
        mirror.apply(new AgentAddedMessage(0, new AgentState("Guppy", body, new Vec3(0, 0, 0), 0, null, List.of(),
                List.of())));
        mirror.apply(new AgentAddedMessage(0, new AgentState("Bunny", body, new Vec3(-3, 0, -3), 0, null, List.of(),
                List.of())));

        Sighting seen = ViewCone.of(mirror, mirror.agent("Guppy").orElseThrow(), 0);

        assertThat(seen.objects()).extracting(Obstacle::id).containsExactly("T1");
        assertThat(seen.fruit()).extracting(FruitState::id).containsExactly("F1");
        assertThat(seen.agents()).extracting(AgentView::name).containsExactly("Bunny");
    }
}
