package io.orchard.server.sim;

import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.PerceivedBridge;
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
import java.util.Arrays;
import java.util.List;

/**
 * Computes what an agent perceives, as the paper has it: limited in range, in direction (the field
 * of view around its heading) and in area (nothing is seen through the castle). Trees, tables and
 * agents come by relative position, fruit by absolute position, landmarks relative, the castle only
 * as a compass sector. Numbers are rounded to centimetres and milliradians ({@link Precision}).
 *
 * <p>What it makes is a {@link Percept}: indices of the things seen and their rounded numbers, no
 * record per thing. Owned by the simulation's thread, which it reuses its arrays for.
 */
final class Perceptions {

    private static final int[] NO_INDICES = new int[0];
    private static final double[] NO_NUMBERS = new double[0];
    private static final String[] NO_NAMES = new String[0];

    private final World world;
    private final Perceivables things;
    /** The simulation thread's scratch space for one view at a time, grown as needed. */
    private final View view = new View();

    Perceptions(World world) {
        this.world = world;
        this.things = new Perceivables(world);
    }

    /** What {@code agent} perceives at {@code tick}, finding others in {@code crowd}. */
    Percept of(Agent agent, CrowdGrid.Query crowd, long tick) {
        view.reset(agent);
        double range = agent.body.sight().range();
        SightBox box = SightBox.of(agent.position.x(), agent.position.z(), range, agent.heading,
                agent.body.sight().fieldOfView());
        world.visitWithin(agent.position.x(), agent.position.z(), range, box, view);
        crowd.forEachInBox(box.minX(), box.minZ(), box.maxX(), box.maxZ(), view);
        Point2 here = agent.position.onGround();
        PerceivedRiver river = null;
        if (!world.riverBeyond(here, range)) {
            RiverPoint nearest = world.nearestRiverPoint(here);
            if (view.sees(nearest.point().x(), nearest.point().z(), nearest.distance())) {
                river = new PerceivedRiver(view.relative(nearest.point().x(), nearest.point().z()),
                        Precision.angle(Angles.normalise(nearest.heading() - agent.heading)));
            }
        }
        List<PerceivedBridge> bridges = List.of();
        for (Bridge bridge : world.bridges()) {
            Point2 a = bridge.entryA();
            Point2 b = bridge.entryB();
            if (view.sees(a.x(), a.z(), here.distance(a)) || view.sees(b.x(), b.z(), here.distance(b))) {
                if (bridges.isEmpty()) {
                    bridges = new ArrayList<>(2);
                }
                bridges.add(new PerceivedBridge(bridge.id(), view.relative(a.x(), a.z()), view.relative(b.x(), b.z()),
                        bridge.width()));
            }
        }
        return new Percept(things, tick, agent.name, Precision.position(agent.position),
                Precision.angle(agent.heading),
                view.objectCount == 0 ? NO_INDICES : Arrays.copyOf(view.objects, view.objectCount),
                view.objectCount == 0 ? NO_NUMBERS : Arrays.copyOf(view.objectPlaces, 2 * view.objectCount),
                view.agentCount == 0 ? NO_NAMES : Arrays.copyOf(view.agents, view.agentCount),
                view.agentCount == 0 ? NO_NUMBERS : Arrays.copyOf(view.agentNumbers, 4 * view.agentCount),
                view.fruitCount == 0 ? NO_INDICES : Arrays.copyOf(view.fruit, view.fruitCount), river, bridges,
                world.castleSector(here));
    }

    /**
     * One agent's view: collects what the world's broad phase and the crowd offer and the cone
     * admits, as indices and rounded numbers in arrays kept from one view to the next.
     */
    private final class View implements NearbyVisitor, CrowdGrid.Visitor {

        private Agent agent;
        private Point2 eye;
        private double eyeX;
        private double eyeZ;
        private double range;
        private double halfField;
        private double facingX;
        private double facingZ;
        private double cosHalfField;
        private boolean castleNear;
        int[] objects = new int[64];
        double[] objectPlaces = new double[128];
        int objectCount;
        String[] agents = new String[8];
        double[] agentNumbers = new double[32];
        int agentCount;
        int[] fruit = new int[16];
        int fruitCount;

        void reset(Agent agent) {
            this.agent = agent;
            this.eye = agent.position.onGround();
            this.eyeX = agent.position.x();
            this.eyeZ = agent.position.z();
            this.range = agent.body.sight().range();
            this.halfField = agent.body.sight().fieldOfView() / 2;
            this.facingX = -Math.sin(agent.heading);
            this.facingZ = -Math.cos(agent.heading);
            this.cosHalfField = Math.cos(halfField);
            this.castleNear = world.castleNear(eye, range);
            objectCount = 0;
            agentCount = 0;
            fruitCount = 0;
        }

        @Override
        public void obstacle(int index, Obstacle obstacle, double x, double z, double distance) {
            if (sees(x, z, distance)) {
                if (objectCount == objects.length) {
                    objects = Arrays.copyOf(objects, 2 * objects.length);
                    objectPlaces = Arrays.copyOf(objectPlaces, 2 * objects.length);
                }
                objects[objectCount] = index;
                place(objectPlaces, 2 * objectCount, x, z);
                objectCount++;
            }
        }

        @Override
        public void fruit(int index, FruitState state, double x, double z, double distance) {
            if (sees(x, z, distance)) {
                if (fruitCount == fruit.length) {
                    fruit = Arrays.copyOf(fruit, 2 * fruit.length);
                }
                fruit[fruitCount++] = index;
            }
        }

        /** Another agent the crowd offers, standing at (x, z). */
        @Override
        public void agent(Agent other, double x, double z) {
            double dx = x - eyeX;
            double dz = z - eyeZ;
            if (other != agent && sees(x, z, Math.sqrt(dx * dx + dz * dz))) {
                if (agentCount == agents.length) {
                    agents = Arrays.copyOf(agents, 2 * agents.length);
                    agentNumbers = Arrays.copyOf(agentNumbers, 4 * agents.length);
                }
                agents[agentCount] = other.name;
                int at = 4 * agentCount;
                place(agentNumbers, at, x, z);
                agentNumbers[at + 2] = Precision.angle(Angles.normalise(other.heading - agent.heading));
                agentNumbers[at + 3] = other.body.radius();
                agentCount++;
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
            return !castleNear || !world.castleHides(eye, new Point2(atX, atZ));
        }

        /** Writes the distance and bearing of (atX, atZ), rounded, at {@code numbers[at]} and the next. */
        private void place(double[] numbers, int at, double atX, double atZ) {
            double dx = atX - eyeX;
            double dz = atZ - eyeZ;
            double distance = Math.sqrt(dx * dx + dz * dz);
            numbers[at] = Precision.length(distance);
            numbers[at + 1] = distance < 1e-9 ? 0
                    : Precision.angle(Angles.normalise(Angles.headingOf(dx, dz) - agent.heading));
        }

        RelativePosition relative(double atX, double atZ) {
            double dx = atX - eyeX;
            double dz = atZ - eyeZ;
            double distance = Math.sqrt(dx * dx + dz * dz);
            return new RelativePosition(Precision.length(distance), distance < 1e-9 ? 0
                    : Precision.angle(Angles.normalise(Angles.headingOf(dx, dz) - agent.heading)));
        }
    }
}
