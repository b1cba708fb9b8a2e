package io.orchard.server.net;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.Unpooled;
import io.netty.channel.embedded.EmbeddedChannel;
import io.netty.handler.codec.LineBasedFrameDecoder;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GraspResultMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.BodyLimits;
import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.ClientSession;
import io.orchard.server.sim.EncodedLine;
import io.orchard.server.sim.Inbox;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.sim.TestWorlds;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The server's message handling under fuzzed input, with two invariants checked after every
 * input. The fuzzed client talks to a real pipeline (framing, flood guard, decoder, session) in
 * front of a simulation; a second, shadow simulation receives only the messages the first one
 * accepted. Rejected messages must change nothing, so the two games must be alike at the end; and
 * a well-formed client must still be answered. Any exception, and any {@code internal_error}, is a
 * failure.
 */
final class ServerUnderFuzz {

    private static final MessageCodec CODEC = new MessageCodec();
    private static final Body BODY = new Body(0.5, 1.2, 10, new Gripper("hands", 0.6, 0, 1.5), new Sight(40, Math.PI));
    private static final Map<String, Vec3> PLACES = Map.of("Guppy", Vec3.ground(0, 0), "Bunny", Vec3.ground(-20, -15));

    /** Hands messages to the simulation and remembers the last one. */
    private static final class Remembering implements Inbox {
        private final Simulation sim;
        ClientMessage last;

        Remembering(Simulation sim) {
            this.sim = sim;
        }

        @Override
        public void connected(ClientSession session) {
            sim.connected(session);
        }

        @Override
        public void received(ClientSession session, ClientMessage message) {
            last = message;
            sim.received(session, message);
        }

        @Override
        public void disconnected(ClientSession session, String reason) {
            sim.disconnected(session, reason);
        }

        @Override
        public WelcomeMessage welcome(long seq, Role role, int protocolVersion) {
            return sim.welcome(seq, role, protocolVersion);
        }
    }

    /** A session that drops what it is sent. */
    private record Quiet(long id, Role role) implements ClientSession {
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

    private final Simulation real = simulation();
    private final Simulation shadow = simulation();
    private final Remembering inbox = new Remembering(real);
    private final SessionContext context = SessionContext.of(inbox, null, NetLimits.DEFAULT);
    private final EmbeddedChannel client = channel();
    private final Quiet shadowClient = new Quiet(1, Role.AGENT);
    private int steps;

    ServerUnderFuzz() {
        Quiet honest = new Quiet(100, Role.AGENT);
        Quiet honestShadow = new Quiet(100, Role.AGENT);
        real.connected(honest);
        shadow.connected(honestShadow);
        shadow.connected(shadowClient);
        real.received(honest, new RegisterMessage(1, "Bunny", BODY, null));
        shadow.received(honestShadow, new RegisterMessage(1, "Bunny", BODY, null));
        write(client, "{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"agent\",\"client\":\"fuzz\"}");
        RegisterMessage guppy = new RegisterMessage(2, "Guppy", BODY, null);
        write(client, CODEC.encode(guppy));
        shadow.received(shadowClient, guppy);
        real.applyNow();
        shadow.applyNow();
        client.runPendingTasks();
        assertThat(replies(client)).anyMatch(m -> m instanceof io.orchard.protocol.message.RegisteredMessage);
    }

    private static Simulation simulation() {
        return new Simulation(TestWorlds.small(), new SimulationConfig(20, ClockMode.LOCKSTEP, 30, 0,
                Duration.ofSeconds(1), 8, BodyLimits.DEFAULT), 7, "fuzz", Recorder.NONE, List.of(), (name, r) ->
                PLACES.get(name));
    }

    private EmbeddedChannel channel() {
        return new EmbeddedChannel(new LineBasedFrameDecoder(MessageCodec.MAX_LARGE_LINE_BYTES + 1, true, true),
                new FloodGuard(1e9, 1e9, () -> 0L), new MessageDecoder(CODEC),
                new SessionHandler(context));
    }

    private static void write(EmbeddedChannel channel, String line) {
        write(channel, line.getBytes(StandardCharsets.UTF_8));
    }

    private static void write(EmbeddedChannel channel, byte[] line) {
        ByteBuf bytes = Unpooled.buffer(line.length + 1).writeBytes(line).writeByte('\n');
        channel.writeInbound(bytes);
        channel.checkException();
    }

    /** Everything the server sent this channel since last asked, decoded. */
    private static List<ServerMessage> replies(EmbeddedChannel channel) {
        List<ServerMessage> out = new ArrayList<>();
        Object message;
        while ((message = channel.readOutbound()) != null) {
            if (message instanceof ByteBuf bytes) {
                // A tick's messages arrive in one buffer, a line each.
                for (String line : bytes.toString(StandardCharsets.UTF_8).split("\n")) {
                    out.add(CODEC.decodeServer(line));
                }
                bytes.release();
            } else {
                out.add((ServerMessage) message);
            }
        }
        for (ServerMessage reply : out) {
            if (reply instanceof ErrorMessage error) {
                assertThat(error.code()).as("the server failed: %s", error.text()).isNotEqualTo(ErrorCode.INTERNAL_ERROR);
            }
        }
        return out;
    }

    /** Sends one fuzzed line and runs one tick in both games; the shadow gets the line only if it was accepted. */
    void step(byte[] line) {
        steps++;
        inbox.last = null;
        if (client.isOpen()) {
            write(client, line);
        }
        real.beginTick();
        real.endTick();
        client.runPendingTasks();
        List<ServerMessage> out = replies(client);
        ClientMessage decoded = inbox.last;
        shadow.beginTick();
        if (decoded != null && accepted(decoded, out)) {
            shadow.received(shadowClient, decoded);
        }
        shadow.endTick();
    }

    private static boolean accepted(ClientMessage message, List<ServerMessage> out) {
        for (ServerMessage reply : out) {
            if (!(reply instanceof Reply answer) || answer.seq() != message.seq()) {
                continue;
            }
            if (reply instanceof ErrorMessage
                    || reply instanceof ActionResultMessage result && result.outcome() == Outcome.REJECTED
                    || reply instanceof GraspResultMessage grasp && !grasp.success()) {
                return false;
            }
        }
        return true;
    }

    /** The invariants: both games alike (rejected lines changed nothing), and a new client is answered. */
    void check() {
        assertThat(withoutTokens(real.checkpoint())).as("the game after %d lines, against the game that saw only "
                + "the accepted ones", steps).isEqualTo(withoutTokens(shadow.checkpoint()));
        EmbeddedChannel fresh = channel();
        write(fresh, "{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"agent\",\"client\":\"check\"}");
        assertThat(replies(fresh)).first().isInstanceOf(WelcomeMessage.class);
        write(fresh, CODEC.encode(new RegisterMessage(77, "Check", BODY, null)));
        real.beginTick();
        real.endTick();
        fresh.runPendingTasks();
        assertThat(replies(fresh)).as("the answer to a well-formed registration")
                .anyMatch(m -> m instanceof Reply reply && reply.seq() == 77);
    }

    private static Checkpoint withoutTokens(Checkpoint checkpoint) {
        return new Checkpoint(checkpoint.format(), checkpoint.seed(), checkpoint.tickRate(), checkpoint.clock(),
                checkpoint.timeLimit(), checkpoint.waitFor(), checkpoint.phase(), checkpoint.tick(), checkpoint.time(),
                checkpoint.fruitAtStart(), checkpoint.world(), checkpoint.agents().stream()
                .map(a -> new Checkpoint.SavedAgent(a.name(), a.body(), a.model(), a.position(), a.heading(),
                        a.joints(), a.timeSensors(), "-")).toList(), checkpoint.scores());
    }

    /** Runs a whole fuzzed input: up to 40 lines, then the checks. */
    static void run(FuzzSource source) {
        ServerUnderFuzz server = new ServerUnderFuzz();
        FuzzedLines lines = new FuzzedLines(source);
        for (int i = 0; i < 40 && source.more(); i++) {
            server.step(lines.next());
        }
        server.check();
    }
}
