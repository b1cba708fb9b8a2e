package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.LeanPerceptionMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.CastleShape;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.ObjectKind;
import io.orchard.protocol.value.Obstacle;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RiverShape;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.BodyLimits;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;
import io.orchard.server.sim.Percept;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import io.orchard.server.world.scenario.Scenario;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The lean writer, which writes a perception from its numbers and the world's tuples encoded once,
 * must write exactly the codec's bytes for the lean record made of the perception's three ordinary
 * messages: checked on real perceptions of agents walking about two worlds, the benchmark's (many
 * things, the river, bridges, the castle) and a small one whose ids need escaping.
 */
class LeanLinesTest {

    private static final MessageCodec CODEC = new MessageCodec();

    /** Keeps the perceptions it is sent. */
    private static final class Perceiving implements ClientSession {
        private final long id;
        final List<Percept> seen = new ArrayList<>();

        Perceiving(long id) {
            this.id = id;
        }

        @Override
        public long id() {
            return id;
        }

        @Override
        public Role role() {
            return Role.AGENT;
        }

        @Override
        public void send(Percept percept) {
            seen.add(percept);
        }

        @Override
        public void send(ServerMessage message) {}

        @Override
        public void send(EncodedLine line) {}

        @Override
        public void flush() {}

        @Override
        public void close(ErrorMessage last) {}

        @Override
        public boolean isOpen() {
            return true;
        }
    }

    private static void same(Percept seen) {
        ByteBuf out = Unpooled.buffer();
        LeanLines.write(seen, out);
        List<ServerMessage> parts = seen.messages();
        assertThat(out.toString(StandardCharsets.UTF_8)).isEqualTo(new String(CODEC.encodeLine(
                LeanPerceptionMessage.of((PerceptionMessage) parts.get(0), (LandmarkPerceptionMessage) parts.get(1),
                        (CastlePerceptionMessage) parts.get(2))), StandardCharsets.UTF_8));
    }

    /**
     * Plays {@code ticks} ticks of {@code agents} agents that walk a few units a tick wherever the
     * world lets them, each perceiving every tick, and checks every perception; returns them.
     */
    private static List<Percept> play(World world, int agents, Sight sight, int ticks) {
        BodyLimits limits = new BodyLimits(0.2, 2.0, 4.0, 20.0, 2.5, 4.0, 500.0);
        Simulation sim = new Simulation(world, new SimulationConfig(20, ClockMode.LOCKSTEP, 1e6, 0,
                Duration.ofSeconds(1), agents, limits), 7, "test", Recorder.NONE, List.of());
        Body body = new Body(0.5, 1.5, 10, new Gripper("hands", 0.6, 0, 1.5), sight);
        List<Perceiving> clients = new ArrayList<>();
        long seq = 0;
        for (int i = 0; i < agents; i++) {
            Perceiving client = new Perceiving(i + 1);
            clients.add(client);
            sim.connected(client);
            sim.received(client, new RegisterMessage(++seq, "A" + i, body, null));
            sim.received(client, new PerceptionRequestMessage(++seq, "A" + i, 1));
        }
        sim.applyNow();
        sim.start();
        SplittableRandom random = new SplittableRandom(5);
        List<Percept> all = new ArrayList<>();
        for (int tick = 0; tick < ticks; tick++) {
            clients.forEach(client -> client.seen.clear());
            sim.beginTick();
            for (int i = 0; i < agents; i++) {
                Perceiving client = clients.get(i);
                assertThat(client.seen).hasSize(1);
                Percept seen = client.seen.get(0);
                same(seen);
                all.add(seen);
                Vec3 here = seen.position();
                sim.received(client, new MoveMessage(++seq, "A" + i, here, Vec3.ground(
                        here.x() + random.nextDouble(-4, 4), here.z() + random.nextDouble(-4, 4))));
            }
            sim.endTick();
        }
        return all;
    }

    /**
     * A perception handed to a session as its three ordinary messages (as a cluster's gateway hands
     * on what its tick sent) reaches a client that reads the lean form as the same lean line, and
     * any other client as the three lines.
     */
    @Test
    void aPerceptionSentAsItsThreeMessagesIsTheSameLeanLine() {
        Percept seen = play(WorldGenerator.benchmark(2026).generate(), 3, new Sight(50, Math.toRadians(120)), 2).get(5);
        for (ClientForms forms : List.of(new ClientForms(true, false), ClientForms.ORDINARY)) {
            ByteBuf fromPercept = Unpooled.buffer();
            ByteBuf fromMessages = Unpooled.buffer();
            assertThat(TickLines.write(List.of(seen), 0, forms, fromPercept)).isEqualTo(1);
            assertThat(TickLines.write(seen.messages(), 0, forms, fromMessages)).isEqualTo(3);
            assertThat(fromMessages.toString(StandardCharsets.UTF_8)).as("the lines for %s", forms)
                    .isEqualTo(fromPercept.toString(StandardCharsets.UTF_8));
        }
    }

    @Test
    void perceptionsOfTheBenchmarkWorldAreWrittenAsTheCodecWritesTheirLeanRecord() {
        List<Percept> seen = play(WorldGenerator.benchmark(2026).generate(), 300, new Sight(50, Math.toRadians(120)), 6);

        // Every part of a perception was written at least once.
        assertThat(seen).anyMatch(p -> p.objectCount() > 0).anyMatch(p -> p.agentCount() > 0)
                .anyMatch(p -> p.fruitCount() > 0);
        assertThat(seen.stream().flatMap(p -> p.messages().stream())).anyMatch(m -> m instanceof PerceptionMessage p
                && p.fruit().stream().anyMatch(f -> f.support() != null) && p.fruit().stream()
                .anyMatch(f -> f.support() == null));
    }

    @Test
    void aWideSightSeesMoreThanAViewFirstHasRoomForAndIsWrittenAsTheCodecWritesIt() {
        List<Percept> seen = play(WorldGenerator.benchmark(2026).generate(), 100, new Sight(150, 2 * Math.PI), 2);

        assertThat(seen).anyMatch(p -> p.objectCount() > 200).anyMatch(p -> p.fruitCount() > 40)
                .anyMatch(p -> p.agentCount() > 12);
    }

    @Test
    void idsThatNeedEscapingAndEveryLandmarkAreWrittenAsTheCodecWritesThem() {
        World world = World.fromScenario(new Scenario(Scenario.FORMAT, new Bounds(-30, -30, 30, 30),
                new CastleShape(List.of(new Point2(10, -25), new Point2(20, -25), new Point2(20, -15),
                        new Point2(10, -15)), 10),
                new RiverShape(List.of(new Point2(-30, 12), new Point2(30, 12), new Point2(30, 16), new Point2(-30, 16))),
                List.of(new BridgeShape("B\"1\"", new Point2(0, 10), new Point2(0, 18), 4)),
                List.of(new Obstacle("T\"quoted\"", ObjectKind.TREE, new Point2(0, -10), 2, 6),
                        new Obstacle("T\\1", ObjectKind.TREE, new Point2(-12, -4), 1.5, 4),
                        new Obstacle("Tré", ObjectKind.TREE, new Point2(22, -5), 1.5, 4)),
                List.of(new Obstacle("D☃", ObjectKind.TABLE, new Point2(10, 0), 1, 0.9)),
                List.of(new FruitState("F é", FruitKind.TOMATO, new Vec3(0, 0.15, 5), null),
                        new FruitState("F\"2\"", FruitKind.BANANA, new Vec3(10, 1.15, 0), "D☃"),
                        new FruitState("F3", FruitKind.COCONUT, new Vec3(-11, 3, -4), "T\\1"),
                        new FruitState("F4", FruitKind.TOMATO, new Vec3(-20, 0.15, -20), null))));

        List<Percept> seen = play(world, 12, new Sight(40, Math.toRadians(120)), 20);

        assertThat(seen).anyMatch(p -> p.river() != null).anyMatch(p -> !p.bridges().isEmpty())
                .anyMatch(p -> p.fruitCount() > 0).anyMatch(p -> p.objectCount() > 0);
    }
}
