package io.orchard.web;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.ModelArchive;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Sight;
import io.orchard.server.WorldServer;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import tools.jackson.databind.JsonNode;

/**
 * A glTF sent as a zip of its files ({@code "format":"zip"}), in a real browser: a 1 m by 2 m
 * panel, its buffer and its magenta texture files of their own in the zip, registered by an agent
 * on a real server; followed, the agent is drawn in the texture's colour where it stands.
 */
class ZippedModelPageTest {

    private static final String NAME = "Panel";
    private static WorldServer server;
    private static ProtocolConnection agent;
    private static Chromium browser;

    @BeforeAll
    static void start() throws Exception {
        assertThat(Chromium.installed()).as("Debian's chromium at %s", Chromium.BINARY).isTrue();
        server = WorldServer.builder().port(0).httpPort(0).seed(1998).waitFor(2).start();
        agent = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT, "zip-test", message -> { });
        Body body = new Body(0.5, 2.0, 2.0, new Gripper("hands", 0.5, 0, 1.5), new Sight(20, 3.0));
        ModelSpec model = ModelSpec.of(ModelFormat.ZIP, panel());
        agent.request(seq -> new RegisterMessage(seq, NAME, body, model))
                .get(java.util.concurrent.TimeUnit.SECONDS.toMillis(10), java.util.concurrent.TimeUnit.MILLISECONDS);
        browser = Chromium.start(960, 540);
        browser.open("http://127.0.0.1:" + server.httpPort().orElseThrow() + "/");
        browser.await("window.orchard && orchard.ready && orchard.agents().includes('" + NAME + "')",
                Duration.ofSeconds(60));
        browser.evaluate("orchard.follow('" + NAME + "')");
    }

    @AfterAll
    static void stop() throws Exception {
        if (browser != null) {
            browser.close();
        }
        if (agent != null) {
            agent.close();
        }
        if (server != null) {
            server.close();
        }
    }

    @Test
    void theZippedModelIsDrawnInItsTexturesColourWhereTheAgentStands() throws Exception {
        long deadline = System.nanoTime() + Duration.ofSeconds(30).toNanos();
        int magenta;
        BufferedImage shot;
        do {
            Thread.sleep(300);
            shot = browser.screenshot();
            magenta = magentaAround(shot, middleOfTheAgent());
        } while (magenta < 50 && System.nanoTime() < deadline);
        ImageIO.write(shot, "png", Path.of("target", "zipped-model.png").toFile());
        assertThat(magenta).as("magenta pixels within 20 px of the agent's middle; Chromium said:%n%s",
                browser.log()).isGreaterThanOrEqualTo(50);
    }

    private static double[] middleOfTheAgent() {
        JsonNode p = browser.evaluate("orchard.position('" + NAME + "')");
        JsonNode at = browser.evaluate("orchard.project(" + p.get("x").asDouble() + "," + (p.get("y").asDouble() + 1)
                + "," + p.get("z").asDouble() + ")");
        return new double[] {at.get("x").asDouble(), at.get("y").asDouble()};
    }

    private static int magentaAround(BufferedImage image, double[] at) {
        int count = 0;
        for (int dx = -20; dx <= 20; dx++) {
            for (int dy = -20; dy <= 20; dy++) {
                int x = (int) Math.round(at[0]) + dx;
                int y = (int) Math.round(at[1]) + dy;
                if (x < 0 || y < 0 || x >= image.getWidth() || y >= image.getHeight()) {
                    continue;
                }
                int rgb = image.getRGB(x, y);
                int r = (rgb >> 16) & 0xff;
                int g = (rgb >> 8) & 0xff;
                int b = rgb & 0xff;
                if (r > g + 60 && b > g + 60) {
                    count++;
                }
            }
        }
        return count;
    }

    /** The panel: {@code Panel/panel.gltf}, {@code Panel/panel.bin}, {@code Panel/skin/magenta.png}. */
    private static byte[] panel() throws IOException {
        ByteBuffer bin = ByteBuffer.allocate(4 * 12 + 4 * 8 + 6 * 2).order(ByteOrder.LITTLE_ENDIAN);
        float[][] corners = {{-0.5f, 0}, {0.5f, 0}, {0.5f, 2}, {-0.5f, 2}};
        for (float[] c : corners) {
            bin.putFloat(c[0]).putFloat(c[1]).putFloat(0);
        }
        for (float[] c : corners) {
            bin.putFloat(c[0] + 0.5f).putFloat(c[1] / 2);
        }
        for (int index : new int[] {0, 1, 2, 0, 2, 3}) {
            bin.putShort((short) index);
        }
        String gltf = """
                {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
                 "nodes": [{"name": "Panel", "mesh": 0}],
                 "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2,
                   "material": 0}]}],
                 "materials": [{"doubleSided": true, "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                   "metallicFactor": 0.0}, "emissiveFactor": [0.6, 0.6, 0.6],
                   "emissiveTexture": {"index": 0}}],
                 "textures": [{"source": 0}], "images": [{"uri": "skin/magenta.png"}],
                 "buffers": [{"uri": "panel.bin", "byteLength": 92}],
                 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                   {"buffer": 0, "byteOffset": 48, "byteLength": 32}, {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
                 "accessors": [
                   {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-0.5, 0, 0],
                    "max": [0.5, 2, 0]},
                   {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                   {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
                """;
        BufferedImage image = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        for (int x = 0; x < 4; x++) {
            for (int y = 0; y < 4; y++) {
                image.setRGB(x, y, 0xFF00FF);
            }
        }
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        ImageIO.write(image, "png", png);
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put("Panel/panel.gltf", gltf.getBytes(StandardCharsets.UTF_8));
        files.put("Panel/panel.bin", bin.array());
        files.put("Panel/skin/magenta.png", png.toByteArray());
        return ModelArchive.pack(files);
    }
}
