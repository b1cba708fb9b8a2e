package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.net.NetLimits;
import io.orchard.server.sim.TestWorlds;
import io.orchard.server.world.scenario.Scenario;
import io.orchard.server.world.scenario.ScenarioException;
import io.orchard.server.world.scenario.ScenarioFile;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.lang.management.BufferPoolMXBean;
import java.lang.management.ManagementFactory;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Hostile clients against a server on a real port, over real sockets. Each attacker gets the error
 * docs/security.md documents for it; meanwhile an honest agent plays in the same game, asking for a
 * perception every tick, and must miss no tick and lose no reply (counted, not timed: a busy
 * machine may slow the game, but must not make it drop anything).
 */
class HostileClientsTest {

    private static final MessageCodec CODEC = new MessageCodec();
    private static final String BODY_JSON = "{\"radius\":0.5,\"height\":1.2,\"maxSpeed\":10,\"gripper\":{\"part\":"
            + "\"hands\",\"reach\":0.6,\"minHeight\":0,\"maxHeight\":1.5},\"sight\":{\"range\":30,\"fieldOfView\":3.14}}";

    @TempDir
    Path dir;

    private final List<AutoCloseable> open = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = open.size() - 1; i >= 0; i--) {
            open.get(i).close();
        }
    }

    private WorldServer started(NetLimits limits) throws IOException {
        Path scenario = dir.resolve("small.json");
        ScenarioFile.write(TestWorlds.small().toScenario(), scenario);
        WorldServer server = WorldServer.builder().port(0).seed(11).scenario(scenario).limits(limits)
                .placement((name, radius) -> Map.of("Guppy", Vec3.ground(0, 0), "Bunny", Vec3.ground(-20, -15)).get(name))
                .start();
        open.add(server);
        return server;
    }

    /**
     * The honest agent: it registers, then asks for a perception at every tick it hears of, and counts
     * the ticks and the replies.
     */
    private final class Honest {
        final List<Long> ticks = new CopyOnWriteArrayList<>();
        final List<Reply> wrongReplies = new CopyOnWriteArrayList<>();
        final AtomicInteger asked = new AtomicInteger();
        final AtomicInteger answered = new AtomicInteger();
        final ProtocolConnection connection;
        volatile boolean asking = true;

        Honest(int port) throws Exception {
            connection = ProtocolConnection.connect("127.0.0.1", port, Role.AGENT, "honest", this::heard);
            open.add(connection);
            Reply registered = connection.request(seq -> new RegisterMessage(seq, "Guppy", WorldServerTest.BODY, null))
                    .get(30, TimeUnit.SECONDS);
            assertThat(registered).isInstanceOf(RegisteredMessage.class);
            awaitTicks(3);
        }

        private void heard(ServerMessage message) {
            if (message instanceof TickMessage tick) {
                ticks.add(tick.tick());
                if (asking) {
                    asked.incrementAndGet();
                    connection.request(seq -> new PerceptionRequestMessage(seq, "Guppy", 0)).whenComplete((reply, e) -> {
                        if (reply instanceof ActionResultMessage) {
                            answered.incrementAndGet();
                        } else if (reply != null) {
                            wrongReplies.add(reply);
                        }
                    });
                }
            }
        }

        void awaitTicks(int more) throws InterruptedException {
            int until = ticks.size() + more;
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (ticks.size() < until && System.nanoTime() < end) {
                Thread.sleep(10);
            }
            assertThat(ticks.size()).as("ticks heard").isGreaterThanOrEqualTo(until);
        }

        /** Stops asking, waits for the last replies, and checks that nothing was missed. */
        void missedNothing() throws InterruptedException {
            awaitTicks(2);
            asking = false;
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (answered.get() + wrongReplies.size() < asked.get() && System.nanoTime() < end) {
                Thread.sleep(10);
            }
            assertThat(connection.isOpen()).as("the honest agent is still connected").isTrue();
            assertThat(wrongReplies).as("replies that were not results").isEmpty();
            assertThat(answered.get()).as("replies to the perception requests").isEqualTo(asked.get());
            List<Long> heard = new ArrayList<>(ticks);
            for (int i = 1; i < heard.size(); i++) {
                assertThat(heard.get(i)).as("the tick after " + heard.get(i - 1)).isEqualTo(heard.get(i - 1) + 1);
            }
        }
    }

    /** A client that speaks raw bytes, to send and to leave unread what a well-behaved client never would. */
    private final class Raw implements AutoCloseable {
        final Socket socket = new Socket();
        final OutputStream out;
        BufferedReader in;

        Raw(int port) throws IOException {
            this(port, 0);
        }

        /** A raw client with a small receive buffer, if given, so that it holds little of what it does not read. */
        Raw(int port, int receiveBuffer) throws IOException {
            if (receiveBuffer > 0) {
                socket.setReceiveBufferSize(receiveBuffer);
            }
            socket.connect(new InetSocketAddress("127.0.0.1", port));
            socket.setSoTimeout(30_000);
            out = socket.getOutputStream();
            open.add(this);
        }

        Raw hello(Role role) throws IOException {
            return send("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"" + role.wireName()
                    + "\",\"client\":\"raw\"}");
        }

        Raw send(String line) throws IOException {
            return send(line.getBytes(StandardCharsets.UTF_8));
        }

        Raw send(byte[] line) throws IOException {
            out.write(line);
            if (line.length == 0 || line[line.length - 1] != '\n') {
                out.write('\n');
            }
            out.flush();
            return this;
        }

        String read() throws IOException {
            if (in == null) {
                in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
            }
            try {
                return in.readLine();
            } catch (java.net.SocketException reset) {
                return null;
            }
        }

        /** The next line that contains {@code fragment}, skipping game traffic; null at the end of the stream. */
        String readUntil(String fragment) throws IOException {
            String line;
            while ((line = read()) != null && !line.contains(fragment)) {
                // ticks, snapshots and the like
            }
            return line;
        }

        /** Reads to the end of the stream and returns the last line. */
        String lastLine() throws IOException {
            String last = null;
            String line;
            while ((line = read()) != null) {
                last = line;
            }
            return last;
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }

    private static String code(String code) {
        return "\"code\":\"" + code + "\"";
    }

    // ---- the handshake ---------------------------------------------------------------------------

    @Test
    void aThousandSocketsThatNeverSayHelloAreClosedWithAnErrorAndLockNoOneOut() throws Exception {
        WorldServer server = started(NetLimits.DEFAULT.withHello(Duration.ofSeconds(1), 64));
        Honest honest = new Honest(server.port());
        List<Raw> silent = new ArrayList<>();
        long opening = System.nanoTime();
        for (int i = 0; i < NetLimits.DEFAULT_MAX_CONNECTIONS; i++) {
            silent.add(new Raw(server.port()));
        }
        // At most 64 wait for their Hello at once: all of them while the flood takes less than the
        // 1 s deadline to open, and 64 more for every further second a busy machine takes.
        long wholeSeconds = TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - opening);
        int mayTimeOut = (int) (64 * (1 + wholeSeconds));
        int pushedOut = 0;
        int timedOut = 0;
        for (Raw raw : silent) {
            String error = raw.read();
            assertThat(error).isNotNull();
            if (error.contains(code("too_many_agents"))) {
                pushedOut++;
            } else {
                assertThat(error).contains(code("idle")).contains("no Hello within 1 s");
                timedOut++;
            }
            assertThat(raw.read()).as("closed after the error").isNull();
        }
        // Seconds after the flood, not the 120 s of the idle rule, a new client gets in.
        ProtocolConnection late = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT, "late", m -> { });
        open.add(late);
        assertThat(late.request(seq -> new RegisterMessage(seq, "Bunny", WorldServerTest.BODY, null))
                .get(30, TimeUnit.SECONDS)).isInstanceOf(RegisteredMessage.class);
        assertThat(timedOut).as("timed out of a flood opened in %d whole seconds", wholeSeconds)
                .isLessThanOrEqualTo(mayTimeOut);
        assertThat(pushedOut + timedOut).isEqualTo(NetLimits.DEFAULT_MAX_CONNECTIONS);
        honest.missedNothing();
    }

    // ---- idle ------------------------------------------------------------------------------------

    @Test
    void aViewerThatOnlyListensIsNotClosedForItsSilenceButAnAgentIs() throws Exception {
        WorldServer server = started(new NetLimits(2_000, 4_000, Duration.ofMillis(800), Duration.ofSeconds(10),
                16L << 20));
        Honest honest = new Honest(server.port());
        Raw viewer = new Raw(server.port()).hello(Role.VIEWER);
        Raw agent = new Raw(server.port()).hello(Role.AGENT);
        assertThat(agent.readUntil("\"type\":\"Error\"")).contains(code("idle")).contains("no message for");
        assertThat(agent.read()).isNull();
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(2_500);
        String line;
        int ticks = 0;
        while (System.nanoTime() < end && (line = viewer.read()) != null) {
            assertThat(line).doesNotContain("\"type\":\"Error\"");
            ticks += line.contains("\"type\":\"Tick\"") ? 1 : 0;
        }
        assertThat(ticks).as("ticks the silent viewer heard in 2.5 s, three idle timeouts").isGreaterThan(10);
        honest.missedNothing();
    }

    // ---- bytes that are not UTF-8 ----------------------------------------------------------------

    @Test
    void linesThatAreNotStrictUtf8AreRefusedNamingTheByteAndChangeNothing() throws Exception {
        WorldServer server = started(NetLimits.DEFAULT);
        Honest honest = new Honest(server.port());
        BlockingQueue<ServerMessage> seen = new LinkedBlockingQueue<>();
        open.add(ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER, "viewer", seen::add));
        Raw raw = new Raw(server.port()).hello(Role.AGENT);
        assertThat(raw.read()).contains("Welcome");

        byte[] head = "{\"type\":\"Register\",\"seq\":2,\"name\":\"A".getBytes(StandardCharsets.US_ASCII);
        byte[] tail = ("b\",\"body\":" + BODY_JSON + "}").getBytes(StandardCharsets.US_ASCII);
        raw.send(concat(head, new byte[] {(byte) 0xc1, (byte) 0x81}, tail));
        assertThat(raw.readUntil("\"type\":\"Error\"")).contains(code("malformed_json"))
                .contains("invalid UTF-8 at byte " + head.length).contains("overlong").contains("\"seq\":2");

        byte[] say = "{\"type\":\"Say\",\"seq\":3,\"agent\":\"Guppy\",\"text\":\"..".getBytes(StandardCharsets.US_ASCII);
        raw.send(concat(say, new byte[] {(byte) 0xc0, (byte) 0xaf}, "etc/passwd\"}".getBytes(StandardCharsets.US_ASCII)));
        assertThat(raw.readUntil("\"type\":\"Error\"")).contains(code("malformed_json"))
                .contains("invalid UTF-8 at byte " + say.length);
        raw.send(concat(say, new byte[] {(byte) 0xed, (byte) 0xa0, (byte) 0x80}, "\"}".getBytes(StandardCharsets.US_ASCII)));
        assertThat(raw.readUntil("\"type\":\"Error\"")).contains(code("malformed_json")).contains("surrogate");

        raw.send("{\"type\":\"Register\",\"seq\":4,\"name\":\"Bunny\",\"body\":" + BODY_JSON + "}");
        assertThat(raw.readUntil("Registered")).contains("\"seq\":4");
        List<String> added = new ArrayList<>();
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (!added.contains("Bunny") && System.nanoTime() < end) {
            ServerMessage message = seen.poll(100, TimeUnit.MILLISECONDS);
            if (message instanceof AgentAddedMessage a) {
                added.add(a.agent().name());
            }
            assertThat(message).isNotInstanceOf(io.orchard.protocol.message.SayMessage.class);
        }
        assertThat(added).containsExactly("Guppy", "Bunny");
        honest.missedNothing();
    }

    private static byte[] concat(byte[]... parts) {
        int length = 0;
        for (byte[] part : parts) {
            length += part.length;
        }
        byte[] all = new byte[length];
        int at = 0;
        for (byte[] part : parts) {
            System.arraycopy(part, 0, all, at, part.length);
            at += part.length;
        }
        return all;
    }

    // ---- models ----------------------------------------------------------------------------------

    private static String register(long seq, String name, byte[] model) {
        return "{\"type\":\"Register\",\"seq\":" + seq + ",\"name\":\"" + name + "\",\"body\":" + BODY_JSON
                + ",\"model\":{\"format\":\"glb\",\"data\":\"" + Base64.getEncoder().encodeToString(model) + "\"}}";
    }

    private static byte[] randomBytes(int size, long seed) {
        byte[] bytes = new byte[size];
        new Random(seed).nextBytes(bytes);
        return bytes;
    }

    @Test
    void aModelOneByteOverFourMiBIsRefusedAndOneOfExactlyFourMiBIsTaken() throws Exception {
        WorldServer server = started(NetLimits.DEFAULT);
        Honest honest = new Honest(server.port());
        Raw raw = new Raw(server.port()).hello(Role.AGENT);
        raw.send(register(2, "Bunny", new byte[ModelSpec.MAX_MODEL_BYTES + 1]));
        assertThat(raw.readUntil("\"type\":\"Error\"")).contains(code("invalid_value"))
                .contains("data must decode to at most 4194304 bytes, it decodes to 4194305").contains("\"seq\":2");
        raw.send(register(3, "Bunny", new byte[ModelSpec.MAX_MODEL_BYTES]));
        assertThat(raw.readUntil("Registered")).contains("\"seq\":3");
        honest.missedNothing();
    }

    @Test
    void modelsBeyondAConnectionsShareOrTheServersAreRefusedAndTheSameModelCostsNothingTwice() throws Exception {
        WorldServer server = started(NetLimits.DEFAULT.withModelBytes(2L << 20, 3L << 20));
        Honest honest = new Honest(server.port());
        BlockingQueue<ServerMessage> seen = new LinkedBlockingQueue<>();
        open.add(ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER, "viewer", seen::add));
        byte[] first = randomBytes(1 << 20, 1);
        byte[] second = randomBytes(1 << 20, 2);
        byte[] third = randomBytes(1 << 20, 3);
        Raw one = new Raw(server.port()).hello(Role.AGENT);
        // A refused model is answered at once, the registrations at the next tick: one at a time, then.
        one.send(register(2, "One", first));
        assertThat(one.readUntil("\"seq\":2")).contains("Registered");
        one.send(register(3, "OneAgain", first));
        assertThat(one.readUntil("\"seq\":3")).contains("Registered");
        one.send(register(4, "OneMore", second));
        assertThat(one.readUntil("\"seq\":4")).contains("Registered");
        one.send(register(5, "OneTooMany", new byte[10]));
        assertThat(one.readUntil("\"seq\":5")).contains(code("invalid_value"))
                .contains("a connection may register models of at most 2097152 bytes in all, this one has registered "
                        + "2097152 and this model has 1024");
        Raw two = new Raw(server.port()).hello(Role.AGENT);
        two.send(register(2, "Two", third));
        assertThat(two.readUntil("\"seq\":2")).contains("Registered");
        two.send(register(3, "TwoTooMany", randomBytes(1000, 4)));
        assertThat(two.readUntil("\"seq\":3")).contains(code("invalid_value"))
                .contains("the server holds 3145728 bytes of models, and takes at most 3145728");
        two.send("{\"type\":\"Register\",\"seq\":4,\"name\":\"TwoBundled\",\"body\":" + BODY_JSON
                + ",\"model\":{\"format\":\"bundled\",\"bundled\":\"bunny\"}}");
        assertThat(two.readUntil("\"seq\":4")).contains("Registered");

        Map<String, byte[]> expected = Map.of("One", first, "OneAgain", first, "OneMore", second, "Two", third);
        Map<String, byte[]> models = new java.util.HashMap<>();
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (models.size() < expected.size() && System.nanoTime() < end) {
            if (seen.poll(100, TimeUnit.MILLISECONDS) instanceof AgentAddedMessage a && expected.containsKey(a.agent().name())) {
                models.put(a.agent().name(), a.agent().model().bytes());
            }
        }
        assertThat(models).containsOnlyKeys(expected.keySet());
        expected.forEach((name, bytes) -> assertThat(models.get(name)).as(name).isEqualTo(bytes));
        honest.missedNothing();
    }

    // ---- clients that do not read ----------------------------------------------------------------

    @Test
    void aViewerThatStopsReadingIsCutOffWithItsErrorAndTheOthersMissNothing() throws Exception {
        WorldServer server = started(NetLimits.DEFAULT.withSlowConsumers(Duration.ofSeconds(2), 16L << 20, 256L << 20));
        Honest honest = new Honest(server.port());
        BlockingQueue<ServerMessage> seen = new LinkedBlockingQueue<>();
        open.add(ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER, "viewer", seen::add));
        Raw stalled = new Raw(server.port(), 4096).hello(Role.VIEWER);
        byte[] model = randomBytes(2 << 20, 5);
        ProtocolConnection owner = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT, "owner", m -> { });
        open.add(owner);
        assertThat(owner.request(seq -> new RegisterMessage(seq, "Bunny", WorldServerTest.BODY,
                ModelSpec.of(ModelFormat.GLB, model))).get(30, TimeUnit.SECONDS)).isInstanceOf(RegisteredMessage.class);
        honest.awaitTicks(100); // five seconds at 20 ticks a second: the stalled viewer is cut after two
        assertThat(stalled.lastLine()).contains(code("slow_consumer")).contains("unread for");
        AgentAddedMessage bunny = null;
        while (bunny == null) {
            if (seen.poll(30, TimeUnit.SECONDS) instanceof AgentAddedMessage a && a.agent().name().equals("Bunny")) {
                bunny = a;
            }
        }
        assertThat(bunny.agent().model().bytes()).isEqualTo(model);
        honest.missedNothing();
    }

    /**
     * Agents with the largest models and a crowd of viewers that never read: each model is kept once,
     * every viewer that does not read is cut off with its error, and the game goes on. Small enough
     * for every build by default; {@code -Phostile} runs it at full size (8 agents with models of
     * 4 MiB, 100 viewers, the default limits) and prints what the server's memory did.
     */
    @Test
    void agentsWithLargeModelsAndViewersThatNeverReadCostBoundedMemoryAndStallNoOne() throws Exception {
        int agents = Integer.getInteger("hostile.agents", 2);
        int modelBytes = Integer.getInteger("hostile.modelBytes", 1 << 20);
        int viewers = Integer.getInteger("hostile.viewers", 20);
        Duration grace = Duration.ofMillis(Long.getLong("hostile.graceMillis", 2_000));
        WorldServer server = started(NetLimits.DEFAULT.withSlowConsumers(grace, NetLimits.DEFAULT.maxPendingBytes(),
                NetLimits.DEFAULT.maxPendingBytesInAll()));
        Memory memory = new Memory();
        Honest honest = new Honest(server.port());
        BlockingQueue<ServerMessage> seen = new LinkedBlockingQueue<>();
        open.add(ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER, "viewer", seen::add));
        List<byte[]> models = new ArrayList<>();
        for (int i = 0; i < agents; i++) {
            byte[] model = randomBytes(modelBytes, 100 + i);
            models.add(model);
            String name = "Big" + i;
            ProtocolConnection owner = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT, name, m -> { });
            open.add(owner);
            assertThat(owner.request(seq -> new RegisterMessage(seq, name, WorldServerTest.BODY,
                    ModelSpec.of(ModelFormat.GLB, model))).get(30, TimeUnit.SECONDS)).isInstanceOf(RegisteredMessage.class);
        }
        long started = System.nanoTime();
        List<Raw> stalled = new ArrayList<>();
        for (int i = 0; i < viewers; i++) {
            stalled.add(new Raw(server.port(), 4096).hello(Role.VIEWER));
        }
        // Each stalled viewer has output waiting from the moment it joined (the models), and is cut off
        // once that has waited for the grace (checked every quarter of it, at most every second); then
        // reading shows the error after what its socket held.
        Thread.sleep(grace.toMillis() + Math.min(grace.toMillis() / 4, 1_000) + 1_000);
        for (Raw viewer : stalled) {
            assertThat(viewer.lastLine()).contains(code("slow_consumer"));
        }
        long seconds = (System.nanoTime() - started) / 1_000_000_000L;
        int received = 0;
        while (received < agents) {
            ServerMessage message = seen.poll(30, TimeUnit.SECONDS);
            assertThat(message).as("the reading viewer's messages").isNotNull();
            if (message instanceof AgentAddedMessage a && a.agent().name().startsWith("Big")) {
                int i = Integer.parseInt(a.agent().name().substring(3));
                assertThat(a.agent().model().bytes()).as(a.agent().name()).isEqualTo(models.get(i));
                received++;
            }
        }
        honest.missedNothing();
        memory.stop();
        System.out.printf("%d agents with models of %d bytes, %d viewers that never read: all cut off in %d s;"
                        + " the honest agent heard %d ticks in a row and had %d replies; the heap of this JVM (server and"
                        + " clients) %d MiB before, at most %d MiB; the JDK's direct buffers at most %d MiB%n", agents, modelBytes, viewers, seconds,
                honest.ticks.size(), honest.answered.get(), memory.heapBefore >> 20, memory.heapMax.get() >> 20,
                memory.directMax.get() >> 20);
    }

    /** Samples this JVM's heap and the JDK's direct buffers (where models are kept) ten times a second. */
    private static final class Memory {
        final long heapBefore = heap();
        final AtomicLong heapMax = new AtomicLong();
        final AtomicLong directMax = new AtomicLong();
        final Thread sampler = new Thread(this::sample, "memory");
        volatile boolean running = true;

        Memory() {
            sampler.setDaemon(true);
            sampler.start();
        }

        private static long heap() {
            Runtime runtime = Runtime.getRuntime();
            return runtime.totalMemory() - runtime.freeMemory();
        }

        private void sample() {
            List<BufferPoolMXBean> pools = ManagementFactory.getPlatformMXBeans(BufferPoolMXBean.class);
            while (running) {
                heapMax.accumulateAndGet(heap(), Math::max);
                long direct = pools.stream().filter(p -> p.getName().equals("direct"))
                        .mapToLong(BufferPoolMXBean::getMemoryUsed).sum();
                directMax.accumulateAndGet(direct, Math::max);
                try {
                    Thread.sleep(100);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }

        void stop() throws InterruptedException {
            running = false;
            sampler.join();
        }
    }

    // ---- scenarios -------------------------------------------------------------------------------

    @Test
    void aScenarioOfPlusOrMinus1e308IsRefusedNamingItsFieldsBeforeAnyGeometryIsBuilt() throws Exception {
        Scenario small = TestWorlds.small().toScenario();
        Path file = dir.resolve("huge.json");
        ScenarioFile.write(new Scenario(Scenario.FORMAT, new Bounds(-1e308, -1e308, 1e308, 1e308), small.castle(),
                small.river(), small.bridges(), small.trees(), small.tables(), small.fruit()), file);
        assertThatThrownBy(() -> WorldServer.builder().port(0).scenario(file).start())
                .isInstanceOf(ScenarioException.class)
                .hasMessageContaining("bounds.minX must lie between -10000.0 and 10000.0, was -1.0E308")
                .hasMessageContaining("bounds.maxZ must lie between -10000.0 and 10000.0, was 1.0E308");
    }
}
