package io.orchard.web;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Dwarf;
import io.orchard.agents.zoo.Guppy;
import io.orchard.agents.zoo.Robot;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.BridgeShape;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Role;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.Phase;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import tools.jackson.databind.JsonNode;

/**
 * The page in a real browser, Debian's Chromium headless, against a real server on port 0 with
 * three of the paper's agents: the world appears (pixels at the projected places of the castle, the
 * river and the agents), a spectator's pause is refused, an instruction typed into the page is
 * answered by the agent, and the operator pauses and resumes the game while an agent moves.
 */
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class BrowserViewerTest {

    private static final String OPERATOR_TOKEN = "teacher-secret";
    private static final Duration PATIENCE = Duration.ofSeconds(60);

    private static WorldServer server;
    private static ExecutorService threads;
    private static final List<AgentController> agents = List.of(new Dwarf(), new Robot(), new Guppy());
    private static WorldSnapshotMessage world;
    private static Chromium browser;

    @BeforeAll
    static void startTheGameAndTheBrowser() throws Exception {
        assertThat(Chromium.installed()).as("Debian's chromium at %s (README: what a bare machine needs)",
                Chromium.BINARY).isTrue();
        server = WorldServer.builder().port(0).httpPort(0).seed(1998).operatorToken(OPERATOR_TOKEN).start();
        threads = Executors.newFixedThreadPool(agents.size());
        for (AgentController agent : agents) {
            threads.submit(() -> agent.run("127.0.0.1", server.port()));
        }
        CompletableFuture<WorldSnapshotMessage> snapshot = new CompletableFuture<>();
        // The world as a viewer of the test's own hears it, to know where the page should draw what.
        ProtocolConnection viewer = ProtocolConnection.connect("127.0.0.1", server.port(), Role.VIEWER,
                "browser-test", message -> {
                    if (message instanceof WorldSnapshotMessage s) {
                        snapshot.complete(s);
                    }
                });
        try {
            world = snapshot.get(30, TimeUnit.SECONDS);
        } finally {
            viewer.close();
        }
        browser = Chromium.start(1280, 720);
        browser.open("http://127.0.0.1:" + server.httpPort().orElseThrow() + "/");
        awaitPage("window.orchard && orchard.ready && orchard.agents().length === " + agents.size());
    }

    @AfterAll
    static void stop() throws Exception {
        if (browser != null) {
            browser.close();
        }
        agents.forEach(AgentController::stop);
        if (threads != null) {
            threads.shutdown();
            threads.awaitTermination(10, TimeUnit.SECONDS);
        }
        if (server != null) {
            server.close();
        }
    }

    private static void awaitPage(String expression) throws InterruptedException {
        try {
            browser.await(expression, PATIENCE);
        } catch (AssertionError e) {
            throw new AssertionError(e.getMessage() + "; Chromium said:\n" + browser.log(), e);
        }
    }

    @Test
    @Order(1)
    void theCastleAndTheRiverAreWhereTheyAre() throws IOException {
        BufferedImage shot = browser.screenshot();
        // Kept for a person to look at: target/browser-viewer.png.
        ImageIO.write(shot, "png", Path.of("target", "browser-viewer.png").toFile());
        List<Point2> footprint = world.castle().footprint();
        double cx = footprint.stream().mapToDouble(Point2::x).average().orElseThrow();
        double cz = footprint.stream().mapToDouble(Point2::z).average().orElseThrow();
        int[] castle = pixel(shot, project(cx, world.castle().height(), cz));
        assertThat(grey(castle)).as("castle's roof at (%.1f, %.1f): rgb %s", cx, cz, rgb(castle)).isTrue();

        List<double[]> water = riverPoints();
        assertThat(water).as("points of the river in view").hasSizeGreaterThanOrEqualTo(5);
        long blue = water.stream().filter(p -> blue(pixel(shot, project(p[0], 0.02, p[1])))).count();
        assertThat(blue).as("river points drawn blue, of %d", water.size()).isGreaterThanOrEqualTo(water.size() * 2L / 3);
    }

    @Test
    @Order(2)
    void thePapersAgentsAreDrawnWithTheirOwnModels() throws InterruptedException {
        // The Dwarf and the Robot send X3D, the Guppy VRML97: each read and built, none a placeholder.
        awaitPage("orchard.agents().every(name => orchard.model(name))");
        for (AgentController agent : agents) {
            JsonNode model = browser.evaluate("orchard.model('" + agent.name() + "')");
            assertThat(model.get("placeholder").asBoolean()).as("%s drawn by the placeholder because %s", agent.name(),
                    model.get("reason")).isFalse();
        }
        assertThat(browser.console()).as("what the page logged").noneMatch(line -> line.contains("cannot be shown")
                || line.startsWith("exception"));
    }

    @Test
    @Order(2)
    void theAgentsAreDrawnWhereTheyStand() throws InterruptedException {
        server.pauseGame();
        try {
            awaitQuiet();
            // Seen from above, an agent under a tree's crown is hidden by it: most are in the open.
            List<String> drawn = agents.stream().map(AgentController::name).filter(BrowserViewerTest::drawnAt).toList();
            assertThat(drawn).as("agents drawn at their projected places").hasSizeGreaterThanOrEqualTo(2);
            // Followed, an agent is seen from behind and above, in the middle of the view.
            String followed = agents.get(0).name();
            browser.evaluate("orchard.follow('" + followed + "')");
            awaitQuiet();
            assertThat(drawnAt(followed)).as("%s drawn in the middle of the view when followed", followed).isTrue();
            browser.evaluate("orchard.follow(null)");
        } finally {
            server.resumeGame();
        }
    }

    @Test
    @Order(3)
    void aSpectatorsPauseIsRefused() throws InterruptedException {
        awaitPhase(Phase.RUNNING);
        browser.evaluate("document.getElementById('pause').click()");
        awaitPage("document.getElementById('answer').textContent.includes('forbidden')");
        assertThat(server.phase()).isEqualTo(Phase.RUNNING);
    }

    @Test
    @Order(4)
    void anInstructionTypedIntoThePageIsAnsweredByTheAgent() throws InterruptedException {
        String name = agents.get(0).name();
        browser.evaluate("document.querySelector('#agents li[data-agent=\"" + name + "\"]').click()");
        browser.evaluate("document.getElementById('instruction').focus()");
        browser.type("go to the castle");
        browser.evaluate("document.getElementById('send').click()");
        awaitPage("[...document.querySelectorAll('#said li')].some(li => li.textContent.startsWith('" + name
                + ": '))");
        assertThat(browser.evaluate("document.getElementById('said').textContent").asString())
                .contains("to " + name + ": go to the castle");
    }

    @Test
    @Order(5)
    void theOperatorPausesAndResumesWhileTheAgentsMove() throws InterruptedException {
        browser.evaluate("document.getElementById('token').focus()");
        browser.type(OPERATOR_TOKEN);
        browser.evaluate("document.getElementById('connect').click()");
        awaitPage("orchard.ready && orchard.agents().length === " + agents.size());

        try {
            operator("pause");
            awaitPhase(Phase.PAUSED);
            awaitQuiet();
            Map<String, double[]> before = screenPositions();
            operator("resume");
            awaitPhase(Phase.RUNNING);
            Thread.sleep(3_000);
            operator("pause");
            awaitQuiet();
            Map<String, double[]> after = screenPositions();

            List<String> moved = new ArrayList<>();
            for (String name : before.keySet()) {
                double[] a = before.get(name);
                double[] b = after.get(name);
                if (Math.hypot(a[0] - b[0], a[1] - b[1]) >= 3 && drawnAt(name)) {
                    moved.add(name);
                }
            }
            assertThat(moved).as("agents drawn 3 px or more from where they were: %s, then %s", text(before),
                    text(after)).isNotEmpty();
            operator("resume");
        } finally {
            server.resumeGame();
        }
    }

    private static String text(Map<String, double[]> positions) {
        StringBuilder out = new StringBuilder();
        positions.forEach((name, p) -> out.append(String.format(java.util.Locale.ROOT, "%s (%.0f, %.0f) ", name, p[0],
                p[1])));
        return out.toString().strip();
    }

    private static void awaitPhase(Phase phase) throws InterruptedException {
        long deadline = System.nanoTime() + PATIENCE.toNanos();
        while (server.phase() != phase && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertThat(server.phase()).isEqualTo(phase);
    }

    private static void operator(String command) throws InterruptedException {
        browser.evaluate("document.getElementById('answer').textContent = ''");
        browser.evaluate("document.getElementById('" + command + "').click()");
        awaitPage("document.getElementById('answer').textContent === 'GameControl: accepted'");
    }

    /** Half a second for the last tick and the frames after it: a paused game stands still. */
    private static void awaitQuiet() throws InterruptedException {
        Thread.sleep(500);
    }

    private static Map<String, double[]> screenPositions() {
        Map<String, double[]> positions = new HashMap<>();
        for (AgentController agent : agents) {
            JsonNode p = browser.evaluate("orchard.position('" + agent.name() + "')");
            positions.put(agent.name(), project(p.get("x").asDouble(), p.get("y").asDouble(), p.get("z").asDouble()));
        }
        return positions;
    }

    /**
     * Whether the agent is drawn at the projection of its middle: the pixels there change when it is
     * hidden (the game is paused, so nothing else moves).
     */
    private static boolean drawnAt(String name) {
        JsonNode p = browser.evaluate("orchard.position('" + name + "')");
        double[] at = project(p.get("x").asDouble(), p.get("y").asDouble() + p.get("height").asDouble() / 2,
                p.get("z").asDouble());
        BufferedImage shown = browser.screenshot();
        browser.evaluate("orchard.show('" + name + "', false)");
        BufferedImage hidden = browser.screenshot();
        browser.evaluate("orchard.show('" + name + "', true)");
        // Around the point: a far agent is a few pixels wide, and its middle may fall between two.
        for (int dx = -2; dx <= 2; dx++) {
            for (int dy = -2; dy <= 2; dy++) {
                int[] a = pixel(shown, new double[] {at[0] + dx, at[1] + dy});
                int[] b = pixel(hidden, new double[] {at[0] + dx, at[1] + dy});
                if (Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]) > 30) {
                    return true;
                }
            }
        }
        return false;
    }

    private static double[] project(double x, double y, double z) {
        JsonNode p = browser.evaluate("orchard.project(" + x + "," + y + "," + z + ")");
        return new double[] {p.get("x").asDouble(), p.get("y").asDouble()};
    }

    private static int[] pixel(BufferedImage image, double[] at) {
        int x = (int) Math.round(at[0]);
        int y = (int) Math.round(at[1]);
        assertThat(x).as("x of a point in view").isBetween(0, image.getWidth() - 1);
        assertThat(y).as("y of a point in view").isBetween(0, image.getHeight() - 1);
        int argb = image.getRGB(x, y);
        return new int[] {(argb >> 16) & 0xff, (argb >> 8) & 0xff, argb & 0xff};
    }

    /** Points well inside the river, away from its bridges, on a grid over the middle of the world. */
    private static List<double[]> riverPoints() {
        Path2D.Double river = new Path2D.Double();
        List<Point2> outline = world.river().outline();
        river.moveTo(outline.get(0).x(), outline.get(0).z());
        outline.stream().skip(1).forEach(p -> river.lineTo(p.x(), p.z()));
        river.closePath();
        List<double[]> points = new ArrayList<>();
        for (double x = -60; x <= 60; x += 10) {
            for (double z = -80; z <= 80; z += 1) {
                if (river.contains(x - 1.5, z) && river.contains(x + 1.5, z) && river.contains(x, z - 1.5)
                        && river.contains(x, z + 1.5) && farFromBridges(x, z)) {
                    points.add(new double[] {x, z});
                    break;
                }
            }
        }
        return points;
    }

    private static boolean farFromBridges(double x, double z) {
        for (BridgeShape bridge : world.bridges()) {
            double mx = (bridge.entryA().x() + bridge.entryB().x()) / 2;
            double mz = (bridge.entryA().z() + bridge.entryB().z()) / 2;
            if (Math.hypot(x - mx, z - mz) < bridge.width() + 8) {
                return false;
            }
        }
        return true;
    }

    private static boolean grey(int[] c) {
        return Math.abs(c[0] - c[1]) < 30 && Math.abs(c[1] - c[2]) < 30 && c[0] > 90;
    }

    private static boolean blue(int[] c) {
        return c[2] > c[0] + 30 && c[2] > c[1] + 10;
    }

    private static String rgb(int[] c) {
        return c[0] + "," + c[1] + "," + c[2];
    }
}
