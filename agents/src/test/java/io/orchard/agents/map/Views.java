package io.orchard.agents.map;

import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.PerceivedRiver;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;

/**
 * Builds the perceptions a server would send an agent standing at a place with a heading, from
 * things given in world coordinates: what tests feed a memory. Conversions follow the protocol's
 * section 3.3, written out here independently of {@link Bearings}.
 */
public final class Views {

    private final Point2 at;
    private final double heading;
    private final List<PerceivedObject> objects = new ArrayList<>();
    private final List<PerceivedAgent> agents = new ArrayList<>();
    private final List<PerceivedFruit> fruit = new ArrayList<>();
    private final List<PerceivedBridge> bridges = new ArrayList<>();
    private PerceivedRiver river;
    private Sector castle = Sector.NORTH;
    private long tick;

    private Views(Point2 at, double heading) {
        this.at = at;
        this.heading = heading;
    }

    /** A view from {@code (x, z)} facing {@code heading}. */
    public static Views from(double x, double z, double heading) {
        return new Views(new Point2(x, z), heading);
    }

    public Views tick(long value) {
        this.tick = value;
        return this;
    }

    public Views tree(String id, double x, double z, double crown) {
        objects.add(new PerceivedObject(id, ObjectKind.TREE, relative(x, z), crown, 6));
        return this;
    }

    public Views table(String id, double x, double z, double radius, double height) {
        objects.add(new PerceivedObject(id, ObjectKind.TABLE, relative(x, z), radius, height));
        return this;
    }

    public Views agent(String name, double x, double z) {
        agents.add(new PerceivedAgent(name, relative(x, z), 0, 0.4));
        return this;
    }

    public Views fruit(String id, FruitKind kind, double x, double y, double z) {
        fruit.add(new PerceivedFruit(id, kind, new Vec3(x, y, z), kind.radius(), null));
        return this;
    }

    /** A fruit lying on a table or hanging in a tree: {@code support} is its id. */
    public Views fruit(String id, FruitKind kind, double x, double y, double z, String support) {
        fruit.add(new PerceivedFruit(id, kind, new Vec3(x, y, z), kind.radius(), support));
        return this;
    }

    /** The river's nearest bank point and the heading in which the river runs there. */
    public Views river(double x, double z, double runs) {
        river = new PerceivedRiver(relative(x, z), normalise(runs - heading));
        return this;
    }

    public Views bridge(String id, double ax, double az, double bx, double bz, double width) {
        bridges.add(new PerceivedBridge(id, relative(ax, az), relative(bx, bz), width));
        return this;
    }

    public Views castle(Sector sector) {
        this.castle = sector;
        return this;
    }

    public PerceptionMessage perception() {
        return new PerceptionMessage(tick, "Tester", at.at(0), heading, objects, agents, fruit);
    }

    public LandmarkPerceptionMessage landmarks() {
        return new LandmarkPerceptionMessage(tick, "Tester", river, bridges);
    }

    public CastlePerceptionMessage castleMessage() {
        return new CastlePerceptionMessage(tick, "Tester", castle);
    }

    /** Feeds the three messages to a memory. */
    public void into(WorldMemory memory) {
        memory.perceive(perception(), landmarks(), castleMessage());
    }

    private RelativePosition relative(double x, double z) {
        double dx = x - at.x();
        double dz = z - at.z();
        double distance = Math.hypot(dx, dz);
        double bearing = distance == 0 ? 0 : normalise(Math.atan2(-dx, -dz) - heading);
        return new RelativePosition(distance, bearing);
    }

    private static double normalise(double angle) {
        double a = Math.IEEEremainder(angle, 2 * Math.PI);
        return a <= -Math.PI ? a + 2 * Math.PI : a;
    }
}
