package io.orchard.viewer.world;

import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import java.util.ArrayList;
import java.util.List;

/**
 * What an agent perceives, by the protocol's rules (its section 3.4): what lies in its view cone.
 * A thing is seen when the ground distance between centres is at most the sight's range, it lies within
 * half the field of view either side of the heading, and the line of sight does not cross the
 * castle. The server's own perception also rounds its numbers; the viewer needs no numbers, only
 * which things are seen, so the two agree but for things exactly on an edge of the cone.
 */
public final class ViewCone {

    private final List<Point2> castle;
    private final Vec3 eye;
    private final Sight sight;
    private final double facingX;
    private final double facingZ;
    private final double cosHalfField;
    private final boolean allAround;

    private ViewCone(List<Point2> castle, Vec3 eye, double heading, Sight sight) {
        this.castle = castle;
        this.eye = eye;
        this.sight = sight;
        this.facingX = -Math.sin(heading);
        this.facingZ = -Math.cos(heading);
        this.allAround = sight.fieldOfView() >= 2 * Math.PI - 1e-9;
        this.cosHalfField = Math.cos(sight.fieldOfView() / 2);
    }

    /** What {@code agent} perceives at simulated time {@code time} in the world {@code world} knows. */
    public static Sighting of(WorldMirror world, AgentView agent, double time) {
        WorldSnapshotMessage snapshot = world.snapshot().orElse(null);
        if (snapshot == null) {
            return Sighting.NOTHING;
        }
        ViewCone view = new ViewCone(snapshot.castle().footprint(), agent.positionAt(time), agent.heading(),
                agent.body().sight());
        List<Obstacle> objects = new ArrayList<>();
        for (Obstacle obstacle : snapshot.obstacles()) {
            if (view.sees(obstacle.position().x(), obstacle.position().z())) {
                objects.add(obstacle);
            }
        }
        List<AgentView> agents = new ArrayList<>();
        for (AgentView other : world.agents()) {
            Vec3 at = other.positionAt(time);
            if (other != agent && view.sees(at.x(), at.z())) {
                agents.add(other);
            }
        }
        List<FruitState> fruit = new ArrayList<>();
        for (FruitState f : world.fruit()) {
            if (view.sees(f.position().x(), f.position().z())) {
                fruit.add(f);
            }
        }
        return new Sighting(objects, agents, fruit);
    }

    /** Whether an agent at {@code eye} with this heading and sight sees the point (x, z) past {@code castle}. */
    public static boolean sees(List<Point2> castle, Vec3 eye, double heading, Sight sight, double x, double z) {
        return new ViewCone(castle, eye, heading, sight).sees(x, z);
    }

    private boolean sees(double x, double z) {
        double dx = x - eye.x();
        double dz = z - eye.z();
        double distance = Math.sqrt(dx * dx + dz * dz);
        if (distance > sight.range()) {
            return false;
        }
        if (distance > 1e-9 && !allAround && dx * facingX + dz * facingZ < cosHalfField * distance) {
            return false;
        }
        return !Polygons.segmentTouches(castle, eye.x(), eye.z(), x, z);
    }
}
