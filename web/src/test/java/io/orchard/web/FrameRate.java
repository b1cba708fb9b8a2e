package io.orchard.web;

import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisterTimeSensorMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.WorldServer;
import java.lang.management.ManagementFactory;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The browser viewer's benchmark (docs/benchmarks.md): the page's frame rate in headless Chromium
 * with N agents walking with the bundled figure (an X3D model, its walk cycle's TimeSensor looping),
 * overlooking the world and following one agent; and what each connected browser costs the server's
 * JVM (the relay and the server together) and how many bytes a tick it is sent, measured with
 * WebSocket viewers that read every line and draw nothing.
 * Run with the web module's test class path: {@code FrameRate AGENTS BROWSERS}.
 */
final class FrameRate {

    private static final int PER_CONNECTION = 8;
    private static final long SECONDS = 10;

    private FrameRate() {}

    public static void main(String[] args) throws Exception {
        int agents = Integer.parseInt(args[0]);
        int browsers = Integer.parseInt(args[1]);
        try (WorldServer server = WorldServer.builder().port(0).httpPort(0).seed(1998).timeLimit(3600).start()) {
            List<Walkers> walkers = new ArrayList<>();
            for (int first = 0; first < agents; first += PER_CONNECTION) {
                walkers.add(Walkers.register(server.port(), first, Math.min(PER_CONNECTION, agents - first)));
            }
            server.startGame();
            Thread walking = new Thread(() -> walk(walkers), "walkers");
            walking.setDaemon(true);
            walking.start();
            try (Chromium browser = Chromium.start(1280, 720)) {
                browser.open("http://127.0.0.1:" + server.httpPort().orElseThrow() + "/");
                browser.await("window.orchard && orchard.ready && orchard.agents().length === " + agents,
                        java.time.Duration.ofSeconds(120));
                browser.await("orchard.agents().every(a => orchard.model(a) && !orchard.model(a).placeholder)",
                        java.time.Duration.ofSeconds(120));
                double overview = framesPerSecond(browser);
                browser.evaluate("orchard.follow('W0')");
                double following = framesPerSecond(browser);
                System.out.printf(Locale.ROOT, "%d agents: %.1f frames/s in headless Chromium (software WebGL)"
                        + " over the world, %.1f following W0%n", agents, overview, following);
            }
            Cost alone = cost(server, 0);
            Cost with = cost(server, browsers);
            System.out.printf(Locale.ROOT, "server JVM: %.3f CPU s per s with no browser, %.3f with %d: %.4f per"
                    + " browser; each browser sent %.0f bytes a tick (%.1f ticks/s)%n", alone.cpu(), with.cpu(),
                    browsers, (with.cpu() - alone.cpu()) / browsers, with.bytesPerTick(), with.ticksPerSecond());
        }
    }

    private static double framesPerSecond(Chromium browser) throws InterruptedException {
        Thread.sleep(3_000);
        long frames = browser.evaluate("orchard.frames").asLong();
        Thread.sleep(SECONDS * 1000);
        return (browser.evaluate("orchard.frames").asLong() - frames) / (double) SECONDS;
    }

    /** The whole JVM's CPU seconds per second, and what one browser was sent: bytes a tick, ticks a second. */
    private record Cost(double cpu, double bytesPerTick, double ticksPerSecond) {}

    /** The JVM's CPU seconds per second with this many WebSocket viewers connected, and what the first was sent. */
    private static Cost cost(WorldServer server, int browsers) throws Exception {
        List<WebSocket> sockets = new ArrayList<>();
        HttpClient http = HttpClient.newHttpClient();
        AtomicLong bytes = new AtomicLong();
        AtomicLong ticks = new AtomicLong();
        for (int i = 0; i < browsers; i++) {
            boolean counted = i == 0;
            WebSocket socket = http.newWebSocketBuilder().buildAsync(URI.create("ws://127.0.0.1:"
                    + server.httpPort().orElseThrow() + "/socket"), new WebSocket.Listener() {
                        @Override
                        public CompletionStage<?> onText(WebSocket ws, CharSequence data, boolean last) {
                            if (counted) {
                                // The lines are JSON of ASCII: a character is a byte, as on the wire.
                                bytes.addAndGet(data.length());
                                if (data.toString().startsWith("{\"type\":\"Tick\"")) {
                                    ticks.incrementAndGet();
                                }
                            }
                            ws.request(1);
                            return null;
                        }
                    }).join();
            socket.sendText("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":2,\"role\":\"viewer\",\"client\":\"bench\"}",
                    true).join();
            sockets.add(socket);
        }
        Thread.sleep(3_000);
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        long cpu = os.getProcessCpuTime();
        long start = System.nanoTime();
        long bytesBefore = bytes.get();
        long ticksBefore = ticks.get();
        Thread.sleep(SECONDS * 1000);
        double seconds = (System.nanoTime() - start) / 1e9;
        double used = (os.getProcessCpuTime() - cpu) / 1e9 / seconds;
        long sent = bytes.get() - bytesBefore;
        long tickCount = ticks.get() - ticksBefore;
        sockets.forEach(WebSocket::abort);
        return new Cost(used, tickCount > 0 ? sent / (double) tickCount : 0, tickCount / seconds);
    }

    private static void walk(List<Walkers> walkers) {
        Random random = new Random(1998);
        try {
            while (true) {
                for (Walkers w : walkers) {
                    w.step(random);
                }
                Thread.sleep(1_000);
            }
        } catch (Exception e) {
            // the benchmark is over
        }
    }

    /** One connection driving up to eight agents, each walking to and fro near where it was put. */
    private record Walkers(ProtocolConnection connection, List<String> names, List<Vec3> homes) {

        static Walkers register(int port, int first, int count) throws Exception {
            ProtocolConnection connection = ProtocolConnection.connect("127.0.0.1", port, Role.AGENT, "bench",
                    message -> { });
            List<String> names = new ArrayList<>();
            List<Vec3> homes = new ArrayList<>();
            Body body = new Body(0.4, 1.2, 3, new Gripper("hands", 0.6, 0, 1.5), new Sight(20, Math.PI / 2));
            for (int i = first; i < first + count; i++) {
                String name = "W" + i;
                int n = i;
                var reply = connection.request(seq -> new RegisterMessage(seq, "W" + n, body,
                        ModelSpec.bundled("figure"), null)).get(30, TimeUnit.SECONDS);
                if (reply instanceof RegisteredMessage registered) {
                    names.add(name);
                    homes.add(registered.position());
                    // The figure's walk cycle, looping: each frame the page runs its event graph.
                    connection.request(seq -> new RegisterTimeSensorMessage(seq, name, name + "TSWalk"))
                            .get(30, TimeUnit.SECONDS);
                    connection.send(seq -> new StartAnimationMessage(seq, name, name + "TSWalk", true));
                }
            }
            return new Walkers(connection, names, homes);
        }

        void step(Random random) throws Exception {
            for (int i = 0; i < names.size(); i++) {
                Vec3 home = homes.get(i);
                Vec3 to = new Vec3(home.x() + random.nextDouble() * 6 - 3, 0, home.z() + random.nextDouble() * 6 - 3);
                String name = names.get(i);
                connection.send(seq -> new MoveMessage(seq, name, null, to));
            }
        }
    }
}
