package io.orchard.server.sim;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.BridgeShape;
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
import io.orchard.server.world.World;
import io.orchard.server.world.scenario.Scenario;
import java.util.List;

/**
 * A small hand-made world whose every distance is known: a river along z 20..26 with bridges at
 * x = 0 and x = -30, a castle in the north-east, tree T1 north of the origin, table D1 east of it.
 */
public final class TestWorlds {

    static final Body BODY = new Body(0.5, 1.2, 10, new Gripper("hands", 0.6, 0, 1.5), new Sight(40, Math.PI));

    private TestWorlds() {}

    public static World small() {
        return World.fromScenario(new Scenario(Scenario.FORMAT, new Bounds(-50, -50, 50, 50),
                new CastleShape(List.of(new Point2(25, -45), new Point2(45, -45), new Point2(45, -25),
                        new Point2(25, -25)), 10),
                new RiverShape(List.of(new Point2(-50, 20), new Point2(50, 20), new Point2(50, 26), new Point2(-50, 26))),
                List.of(new BridgeShape("B1", new Point2(0, 18), new Point2(0, 28), 4),
                        new BridgeShape("B2", new Point2(-30, 18), new Point2(-30, 28), 4)),
                List.of(new Obstacle("T1", ObjectKind.TREE, new Point2(0, -10), 2, 6)),
                List.of(new Obstacle("D1", ObjectKind.TABLE, new Point2(10, 0), 1, 0.9)),
                List.of(new FruitState("F1", FruitKind.TOMATO, new Vec3(0, 0.15, 5), null),
                        new FruitState("F2", FruitKind.BANANA, new Vec3(10, 1.15, 0), "D1"),
                        new FruitState("F4", FruitKind.TOMATO, new Vec3(-20, 0.15, -20), null),
                        new FruitState("F5", FruitKind.COCONUT, new Vec3(35, 0.35, -48), null))));
    }
}
