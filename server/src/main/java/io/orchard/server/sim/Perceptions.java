package io.orchard.server.sim;

import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.PerceivedRiver;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.world.Bridge;
import io.orchard.server.world.NearbyVisitor;
import io.orchard.server.world.RiverPoint;
import io.orchard.server.world.SightBox;
import io.orchard.server.world.World;
import java.util.ArrayList;
import java.util.List;

/**
 * Computes what an agent perceives, as the paper has it: limited in range, in direction (the field
 * of view around its heading) and in area (nothing is seen through the castle). Trees, tables and
 * agents come by relative position, fruit by absolute position, landmarks relative, the castle only
 * as a compass sector. Numbers are rounded to centimetres and milliradians: agents perceive vaguely
 * anyway, and shorter numbers halve the cost of sending a perception.
 */
final class Perceptions {

    private final World world;

    Perceptions(World world) {
        this.world = world;
    }

    /** The three perception messages for {@code agent} at {@code tick}, finding others in {@code crowd}. */
    List<ServerMessage> of(Agent agent, AgentGrid crowd, long tick) {
        View view = new View(agent);
        double range = agent.body.sight().range();
        SightBox box = SightBox.of(agent.position.x(), agent.position.z(), range, agent.heading,
                agent.body.sight().fieldOfView());
        world.visitWithin(agent.position.x(), agent.position.z(), range, box, view);
        List<PerceivedAgent> others = new ArrayList<>();
        crowd.forEachInBox(box.minX(), box.minZ(), box.maxX(), box.maxZ(), other -> {
            if (other != agent && view.sees(other.position.x(), other.position.z(),
                    agent.position.groundDistance(other.position))) {
                others.add(new PerceivedAgent(other.name, view.relative(other.position.x(), other.position.z()),
                        round3(Angles.normalise(other.heading - agent.heading)), other.body.radius()));
            }
        });
        PerceptionMessage perception = new PerceptionMessage(tick, agent.name, round(agent.position),
                round3(agent.heading), view.objects, others, view.fruit);
        return List.of(perception, landmarks(agent, view, tick),
                new CastlePerceptionMessage(tick, agent.name, world.castleSector(agent.position.onGround())));
    }

    private LandmarkPerceptionMessage landmarks(Agent agent, View view, long tick) {
        Point2 here = agent.position.onGround();
        PerceivedRiver river = null;
        if (!world.riverBeyond(here, agent.body.sight().range())) {
            RiverPoint nearest = world.nearestRiverPoint(here);
            if (view.sees(nearest.point().x(), nearest.point().z(), nearest.distance())) {
                river = new PerceivedRiver(view.relative(nearest.point().x(), nearest.point().z()),
                        round3(Angles.normalise(nearest.heading() - agent.heading)));
            }
        }
        List<PerceivedBridge> bridges = new ArrayList<>();
        for (Bridge bridge : world.bridges()) {
            Point2 a = bridge.entryA();
            Point2 b = bridge.entryB();
            if (view.sees(a.x(), a.z(), here.distance(a)) || view.sees(b.x(), b.z(), here.distance(b))) {
                bridges.add(new PerceivedBridge(bridge.id(), view.relative(a.x(), a.z()), view.relative(b.x(), b.z()),
                        bridge.width()));
            }
        }
        return new LandmarkPerceptionMessage(tick, agent.name, river, bridges);
    }

    /** One agent's view: collects what the world's broad phase offers and the cone admits. */
    private final class View implements NearbyVisitor {

        private final Agent agent;
        private final double eyeX;
        private final double eyeZ;
        private final double range;
        private final double halfField;
        private final double facingX;
        private final double facingZ;
        private final double cosHalfField;
        private final boolean castleNear;
        private final List<PerceivedObject> objects = new ArrayList<>();
        private final List<PerceivedFruit> fruit = new ArrayList<>();

        View(Agent agent) {
            this.agent = agent;
            this.eyeX = agent.position.x();
            this.eyeZ = agent.position.z();
            this.range = agent.body.sight().range();
            this.halfField = agent.body.sight().fieldOfView() / 2;
            this.facingX = -Math.sin(agent.heading);
            this.facingZ = -Math.cos(agent.heading);
            this.cosHalfField = Math.cos(halfField);
            this.castleNear = world.castleNear(agent.position.onGround(), agent.body.sight().range());
        }

        @Override
        public void obstacle(Obstacle obstacle, double x, double z, double distance) {
            if (sees(x, z, distance)) {
                objects.add(new PerceivedObject(obstacle.id(), obstacle.kind(), relative(x, z),
                        obstacle.radius(), obstacle.height()));
            }
        }

        @Override
        public void fruit(FruitState state, double x, double z, double distance) {
            if (sees(x, z, distance)) {
                fruit.add(new PerceivedFruit(state.id(), state.kind(), round(state.position()), state.kind().radius(),
                        state.support()));
            }
        }

        boolean sees(double atX, double atZ, double distance) {
            if (distance > range) {
                return false;
            }
            // Inside the cone when the angle to the facing direction is at most half the field.
            double dx = atX - eyeX;
            double dz = atZ - eyeZ;
            if (distance > 1e-9 && halfField < Math.PI && dx * facingX + dz * facingZ < cosHalfField * distance) {
                return false;
            }
            return !castleNear || !world.castleHides(agent.position.onGround(), new Point2(atX, atZ));
        }

        RelativePosition relative(double atX, double atZ) {
            double dx = atX - eyeX;
            double dz = atZ - eyeZ;
            double distance = Math.sqrt(dx * dx + dz * dz);
            return new RelativePosition(round2(distance), distance < 1e-9 ? 0
                    : round3(Angles.normalise(Angles.headingOf(dx, dz) - agent.heading)));
        }
    }

    static double round2(double value) {
        return Math.round(value * 100) / 100.0;
    }

    static double round3(double value) {
        double rounded = Math.round(value * 1000) / 1000.0;
        return rounded <= -Math.PI ? rounded + 0.001 : Math.min(rounded, Math.PI);
    }

    static Vec3 round(Vec3 v) {
        return new Vec3(round2(v.x()), round2(v.y()), round2(v.z()));
    }
}
