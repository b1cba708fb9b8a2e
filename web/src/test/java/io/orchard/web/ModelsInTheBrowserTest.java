package io.orchard.web;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterJointMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisterTimeSensorMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.SetJointRotationMessage;
import io.orchard.protocol.message.SetRotationMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Rotation;
import io.orchard.protocol.value.Sight;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.Phase;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Predicate;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import tools.jackson.databind.JsonNode;

/**
 * Agents' own X3D and VRML97 models in a real browser, Debian's Chromium headless, against a real
 * server on port 0: each drawn as its geometry (its glowing colours where it stands, not the
 * placeholder), its registered joint turned by the server's JointRotated, its TimeSensor run by
 * AnimationStarted through its ROUTEs; and following an agent: its view cone drawn on the ground
 * ahead of it and not beside it, and what the page says it perceives is what the server's
 * Perception says.
 *
 * <p>The models are this test's own (Crane.x3d, Heron.wrl): a post in one colour with an arm of
 * another, forward from its top, on a DEF'd Transform named Arm; turned +90° about x the arm
 * points up.
 */
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class ModelsInTheBrowserTest {

    private static final Duration PATIENCE = Duration.ofSeconds(60);
    private static final int[] MAGENTA = {255, 0, 255};
    private static final int[] CYAN = {0, 255, 255};
    private static final int[] ORANGE = {255, 128, 0};
    private static final int[] BLUE = {0, 0, 255};
    /** A narrow sight, so that points beside the cone are in the follow camera's view. */
    private static final Sight SIGHT = new Sight(14, Math.PI / 2);

    private static WorldServer server;
    private static ProtocolConnection connection;
    private static Chromium browser;
    private static final Map<String, Vec3> places = new HashMap<>();
    private static final AtomicReference<PerceptionMessage> craneSees = new AtomicReference<>();

    /** A test agent: its name, model file, format and its two colours (post, arm). */
    private record Model(String name, String file, ModelFormat format, int[] post, int[] arm) {}

    private static final Model CRANE = new Model("Crane", "Crane.x3d", ModelFormat.X3D, MAGENTA, CYAN);
    private static final Model HERON = new Model("Heron", "Heron.wrl", ModelFormat.VRML97, ORANGE, BLUE);

    @BeforeAll
    static void registerTheAgentsAndOpenThePage() throws Exception {
        assertThat(Chromium.installed()).as("Debian's chromium at %s (README: what a bare machine needs)",
                Chromium.BINARY).isTrue();
        server = WorldServer.builder().port(0).httpPort(0).seed(1998).timeLimit(3600).start();
        connection = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT, "models-test", message -> {
            if (message instanceof PerceptionMessage p && p.agent().equals(CRANE.name())) {
                craneSees.set(p);
            }
        });
        Body body = new Body(0.5, 2.0, 2, new Gripper("claw", 0.5, 0, 1), SIGHT);
        for (Model model : List.of(CRANE, HERON)) {
            ModelSpec spec = ModelSpec.of(model.format(), bytes(model.file()));
            Reply reply = connection.request(seq -> new RegisterMessage(seq, model.name(), body, spec, null))
                    .get(30, TimeUnit.SECONDS);
            assertThat(reply).as("the server's answer to registering %s", model.name())
                    .isInstanceOf(RegisteredMessage.class);
            places.put(model.name(), ((RegisteredMessage) reply).position());
            accepted(connection.request(seq -> new RegisterJointMessage(seq, model.name(), "Arm")));
            accepted(connection.request(seq -> new RegisterTimeSensorMessage(seq, model.name(), model.name()
                    + "TSRaise")));
            // Facing north, so that the arm points to -z and a camera to the east sees it side on.
            accepted(connection.request(seq -> new SetRotationMessage(seq, model.name(), Rotation.heading(0))));
        }
        // A model the page must refuse: it declares entities, the "billion laughs".
        String laughs = "<?xml version='1.0'?><!DOCTYPE X3D [<!ENTITY a 'haha'><!ENTITY b '&a;&a;&a;&a;&a;'>]>"
                + "<X3D><Scene><Transform DEF='Broken'><Shape><Box size='&b; 1 1'/></Shape></Transform></Scene></X3D>";
        Reply broken = connection.request(seq -> new RegisterMessage(seq, "Broken", body, ModelSpec.of(ModelFormat.X3D,
                laughs.getBytes(java.nio.charset.StandardCharsets.UTF_8)), null)).get(30, TimeUnit.SECONDS);
        assertThat(broken).isInstanceOf(RegisteredMessage.class);
        accepted(connection.request(seq -> new PerceptionRequestMessage(seq, CRANE.name(), 1)));
        server.startGame();
        browser = Chromium.start(1280, 720);
        browser.open("http://127.0.0.1:" + server.httpPort().orElseThrow() + "/");
        browser.await("window.orchard && orchard.ready && orchard.model('Crane') && orchard.model('Heron')"
                + " && orchard.model('Broken')", PATIENCE);
    }

    @AfterAll
    static void stop() {
        if (browser != null) {
            browser.close();
        }
        if (connection != null) {
            connection.close();
        }
        if (server != null) {
            server.close();
        }
    }

    private static byte[] bytes(String file) throws IOException {
        try (InputStream in = ModelsInTheBrowserTest.class.getResourceAsStream("models/" + file)) {
            assertThat(in).as("test model %s", file).isNotNull();
            return in.readAllBytes();
        }
    }

    private static void accepted(java.util.concurrent.CompletableFuture<Reply> request) throws Exception {
        Reply reply = request.get(30, TimeUnit.SECONDS);
        assertThat(reply).isInstanceOfSatisfying(ActionResultMessage.class,
                result -> assertThat(result.outcome().toString()).as("%s", result).isEqualToIgnoringCase("accepted"));
    }

    @Test
    @Order(1)
    void anX3dModelIsDrawnAsItsGeometryWhereItStands() throws Exception {
        drawnAsItsGeometry(CRANE);
    }

    @Test
    @Order(2)
    void aVrml97ModelIsDrawnAsItsGeometryWhereItStands() throws Exception {
        drawnAsItsGeometry(HERON);
    }

    @Test
    @Order(3)
    void clickingAnAgentSelectsIt() throws Exception {
        for (Model model : List.of(CRANE, HERON)) {
            lookFromTheEast(model);
            awaitFrame(shot -> near(shot, post(model), model.post()), model.name() + " in view");
            double[] at = post(model);
            browser.click(at[0], at[1]);
            assertThat(browser.evaluate("document.getElementById('selected').textContent").asString())
                    .as("the agent selected by clicking its post").isEqualTo(model.name());
        }
        // Clicking where no agent is selects no other.
        browser.click(5, 150);
        assertThat(browser.evaluate("document.getElementById('selected').textContent").asString())
                .isEqualTo(HERON.name());
    }

    @Test
    @Order(4)
    void aJointRotatedByTheServerTurnsInThePage() throws Exception {
        for (Model model : List.of(CRANE, HERON)) {
            lookFromTheEast(model);
            assertThat(armForward(model, browser.screenshot())).as("%s's arm forward at first", model.name()).isTrue();
            connection.send(seq -> new SetJointRotationMessage(seq, model.name(), "Arm",
                    new Rotation(new Vec3(1, 0, 0), Math.PI / 2)));
            BufferedImage raised = awaitFrame(shot -> armUp(model, shot), model.name() + "'s arm turned up");
            ImageIO.write(raised, "png", Path.of("target", "browser-joint-" + model.name() + ".png").toFile());
            connection.send(seq -> new SetJointRotationMessage(seq, model.name(), "Arm",
                    new Rotation(new Vec3(1, 0, 0), 0)));
            awaitFrame(shot -> armForward(model, shot), model.name() + "'s arm turned back forward");
        }
    }

    @Test
    @Order(5)
    void aTimeSensorStartedByTheServerRunsThroughItsRoutes() throws Exception {
        awaitPhase(Phase.RUNNING);
        for (Model model : List.of(CRANE, HERON)) {
            lookFromTheEast(model);
            assertThat(armForward(model, browser.screenshot())).as("%s's arm forward before", model.name()).isTrue();
            connection.send(seq -> new StartAnimationMessage(seq, model.name(), model.name() + "TSRaise", false));
            awaitFrame(shot -> armUp(model, shot), model.name() + "'s arm raised by " + model.name() + "TSRaise");
        }
    }

    @Test
    @Order(6)
    void followingAnAgentDrawsItsViewConeAndWhatItPerceives() throws Exception {
        browser.evaluate("orchard.view(null)");
        browser.evaluate("orchard.follow('" + CRANE.name() + "')");
        server.pauseGame();
        awaitPhase(Phase.PAUSED);
        Thread.sleep(500);
        BufferedImage shown = browser.screenshot();
        ImageIO.write(shown, "png", Path.of("target", "browser-follow.png").toFile());
        browser.evaluate("orchard.showFollowing(false)");
        BufferedImage hidden = browser.screenshot();
        browser.evaluate("orchard.showFollowing(true)");

        Vec3 at = places.get(CRANE.name());
        List<String> inside = new ArrayList<>();
        List<String> beside = new ArrayList<>();
        int insideTinted = 0;
        int besideSame = 0;
        // Facing north (-z): bearings to the left are to the west (-x).
        for (double bearing : new double[] {-0.5, -0.25, 0, 0.25, 0.5}) {
            for (double distance : new double[] {5, 8}) {
                double[] p = project(at.x() - distance * Math.sin(bearing), 0, at.z() - distance * Math.cos(bearing));
                int[] a = pixel(shown, p);
                int[] b = pixel(hidden, p);
                inside.add(rgb(b) + " -> " + rgb(a));
                // The cone's yellow over the ground: redder and not bluer.
                if (a[0] - b[0] >= 25 && a[2] - b[2] <= 10) {
                    insideTinted++;
                }
            }
        }
        for (double bearing : new double[] {-1.3, -1.1, 1.1, 1.3}) {
            double[] p = project(at.x() - 5 * Math.sin(bearing), 0, at.z() - 5 * Math.cos(bearing));
            int[] a = pixel(shown, p);
            int[] b = pixel(hidden, p);
            beside.add(rgb(b) + " -> " + rgb(a));
            if (distance(a, b) <= 12) {
                besideSame++;
            }
        }
        assertThat(insideTinted).as("ground points inside the cone drawn yellower: %s", inside).isGreaterThanOrEqualTo(8);
        assertThat(besideSame).as("ground points beside the cone left as they were: %s", beside).isGreaterThanOrEqualTo(3);

        // What the page says the agent perceives is what the server told the agent it perceives.
        PerceptionMessage perception = craneSees.get();
        assertThat(perception).as("a Perception of Crane").isNotNull();
        JsonNode seen = browser.evaluate("orchard.seen()");
        assertThat(strings(seen.get("fruit"))).as("fruit seen")
                .containsExactlyInAnyOrderElementsOf(perception.fruit().stream().map(PerceivedFruit::id).toList());
        assertThat(strings(seen.get("objects"))).as("trees and tables seen")
                .containsExactlyInAnyOrderElementsOf(perception.objects().stream().map(PerceivedObject::id).toList());
        assertThat(strings(seen.get("agents"))).as("agents seen")
                .containsExactlyInAnyOrderElementsOf(perception.agents().stream().map(PerceivedAgent::name).toList());
        assertThat(browser.evaluate("document.getElementById('seen').children.length").asInt())
                .as("lines of the panel's list of what it perceives").isEqualTo(perception.fruit().size()
                        + perception.objects().size() + perception.agents().size());
        server.resumeGame();
    }

    @Test
    @Order(7)
    void aModelThatDeclaresEntitiesIsRefusedAndAPlaceholderStandsIn() {
        JsonNode drawn = browser.evaluate("orchard.model('Broken')");
        assertThat(drawn.get("placeholder").asBoolean()).as("Broken drawn by the placeholder").isTrue();
        assertThat(drawn.get("reason").asString()).contains("entities");
        assertThat(browser.console()).anyMatch(line -> line.contains("agent Broken: its x3d model cannot be shown"));
    }

    private static List<String> strings(JsonNode array) {
        List<String> out = new ArrayList<>();
        array.forEach(node -> out.add(node.asString()));
        return out;
    }

    private static void drawnAsItsGeometry(Model model) throws Exception {
        JsonNode drawn = browser.evaluate("orchard.model('" + model.name() + "')");
        assertThat(drawn.get("placeholder").asBoolean()).as("%s drawn by a placeholder because %s", model.name(),
                drawn.get("reason")).isFalse();
        lookFromTheEast(model);
        BufferedImage shot = awaitFrame(s -> near(s, post(model), model.post()) && armForward(model, s),
                model.name() + " drawn in its colours where the server put it");
        ImageIO.write(shot, "png", Path.of("target", "browser-model-" + model.name() + ".png").toFile());
        browser.evaluate("orchard.show('" + model.name() + "', false)");
        BufferedImage hidden = browser.screenshot();
        browser.evaluate("orchard.show('" + model.name() + "', true)");
        assertThat(near(hidden, post(model), model.post())).as("%s's colour there once it is hidden", model.name())
                .isFalse();
    }

    /** A camera 7 units east of the agent, level with its arm, looking at it: the arm runs leftwards on the screen. */
    private static void lookFromTheEast(Model model) {
        Vec3 at = places.get(model.name());
        browser.evaluate("orchard.follow(null)");
        browser.evaluate(String.format(java.util.Locale.ROOT, "orchard.view([%f, %f, %f, %f, %f, %f])", at.x() + 7,
                at.y() + 2.5, at.z() - 1, at.x(), at.y() + 1.8, at.z() - 1));
    }

    private static double[] post(Model model) {
        Vec3 at = places.get(model.name());
        return project(at.x(), at.y() + 1.0, at.z());
    }

    private static boolean armForward(Model model, BufferedImage shot) {
        Vec3 at = places.get(model.name());
        return near(shot, project(at.x(), at.y() + 1.9, at.z() - 2), model.arm())
                && !near(shot, project(at.x(), at.y() + 1.9 + 2, at.z()), model.arm());
    }

    private static boolean armUp(Model model, BufferedImage shot) {
        Vec3 at = places.get(model.name());
        return near(shot, project(at.x(), at.y() + 1.9 + 2, at.z()), model.arm())
                && !near(shot, project(at.x(), at.y() + 1.9, at.z() - 2), model.arm());
    }

    /** Screenshots until one shows what is wanted, or fails saying what was awaited and what the page logged. */
    private static BufferedImage awaitFrame(Predicate<BufferedImage> wanted, String what) throws InterruptedException {
        long deadline = System.nanoTime() + PATIENCE.toNanos();
        BufferedImage shot = browser.screenshot();
        while (!wanted.test(shot)) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("the page did not show " + what + " within " + PATIENCE.toSeconds()
                        + " s; the page logged: " + browser.console());
            }
            Thread.sleep(200);
            shot = browser.screenshot();
        }
        return shot;
    }

    private static void awaitPhase(Phase phase) throws InterruptedException {
        long deadline = System.nanoTime() + PATIENCE.toNanos();
        while (server.phase() != phase && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertThat(server.phase()).isEqualTo(phase);
    }

    /** Whether a pixel within two of the point has this colour (the model's glow is drawn unlit, as it is). */
    private static boolean near(BufferedImage shot, double[] at, int[] colour) {
        for (int dx = -2; dx <= 2; dx++) {
            for (int dy = -2; dy <= 2; dy++) {
                if (distance(pixel(shot, new double[] {at[0] + dx, at[1] + dy}), colour) <= 40) {
                    return true;
                }
            }
        }
        return false;
    }

    private static int distance(int[] a, int[] b) {
        return Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]);
    }

    private static double[] project(double x, double y, double z) {
        // Drawn first, so that the projection is the camera's of the frame the next screenshot shows.
        browser.evaluate("orchard.draw()");
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

    private static String rgb(int[] c) {
        return c[0] + "," + c[1] + "," + c[2];
    }
}
