package io.orchard.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.value.ModelFit;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.model.TestModels;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.LongFunction;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code totem.x3d}, an X3D file written for the tests with a remote DTD, a prototype of two
 * instances, a Text label, centimetres and an origin 2.5 m off its centre, registered through a
 * live server at the origin with a body 1.6 m tall: it stands there at the body's height, red block
 * below and blue head above, and its time sensor tilts the head; the same file asked for as authored
 * stands where its author put it, its centimetres taken for metres, 250 m off to the side. The Text is reported, not drawn.
 */
class HeadlessX3dModelTest {

    static final Vec3 CAMERA = new Vec3(0, 1.2, 5);
    static final Vec3 TARGET = new Vec3(0, 1, 0);
    static final Frame.ColorTest RED = (r, g, b) -> r > 100 && r > g + 60 && r > b + 60;
    static final Frame.ColorTest BLUE = (r, g, b) -> b > 100 && b > r + 60 && b > g + 30;

    @TempDir
    static Path dir;
    static ViewerProcess.Result fitted;
    static ViewerProcess.Result authored;
    static Frame before;
    static Frame during;
    static Frame asAuthored;

    @BeforeAll
    static void playAndTakeTheScreenshots() throws Exception {
        ViewerProcess.xvfbRun();
        byte[] totem = TestModels.resource("totem.x3d");
        Map<Long, List<LongFunction<ClientMessage>>> script = new HashMap<>();
        GameFixture.at(script, 10, seq -> new StartAnimationMessage(seq, "Totem", "TotemTSNod", true));
        Path recording = GameFixture.posing(dir, "Totem", ModelSpec.of(ModelFormat.X3D, totem),
                List.of("TotemTSNod"), script, 2);
        fitted = ViewerProcess.run(dir, false, "--replay", recording.toString(), "--headless", "--size", "640x360",
                "--hud", "off", "--camera", "0,1.2,5", "--look-at", "0,1,0",
                "--screenshot", "before.png", "--at", "0.4", "--screenshot", "during.png", "--at", "1.0");
        assertThat(fitted.exit()).as("exit status; output:%n%s", fitted.output()).isZero();
        // Kept for a person to look at: target/totem-*.png.
        for (String shot : List.of("before", "during")) {
            java.nio.file.Files.copy(dir.resolve(shot + ".png"), Path.of("target", "totem-" + shot + ".png"),
                    java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        before = Frame.read(dir.resolve("before.png"), CAMERA, TARGET);
        during = Frame.read(dir.resolve("during.png"), CAMERA, TARGET);

        Path plain = dir.resolve("authored");
        java.nio.file.Files.createDirectories(plain);
        Path asIs = GameFixture.posing(plain, "Totem", ModelSpec.of(ModelFormat.X3D, totem).withFit(ModelFit.AUTHORED),
                List.of(), Map.of(), 1);
        authored = ViewerProcess.run(plain, false, "--replay", asIs.toString(), "--headless", "--size", "640x360",
                "--hud", "off", "--camera", "0,1.2,5", "--look-at", "0,1,0", "--screenshot", "authored.png",
                "--at", "0.5");
        assertThat(authored.exit()).as("exit status; output:%n%s", authored.output()).isZero();
        asAuthored = Frame.read(plain.resolve("authored.png"), CAMERA, TARGET);
    }

    @Test
    void theModelLoadsAndItsTextIsReportedNotDrawn() {
        assertThat(fitted.output()).doesNotContain("placeholder", "cannot be shown");
        assertThat(fitted.output()).contains("Text").contains("not drawn");
    }

    @Test
    void itStandsWhereTheAgentIsAtTheBodysHeight() {
        // 180 cm fitted to 1.6 m: the red block from 0 to 0.89 m, 0.53 m wide; the head up to 1.6 m.
        assertThat(before.countNear(new Vec3(0, 0.45, 0), 3, RED)).as("block at the agent's place").isEqualTo(49);
        assertThat(before.countNear(new Vec3(0, 1.25, 0), 3, BLUE)).as("head above it").isEqualTo(49);
        assertThat(before.countNear(new Vec3(0, 1.75, 0), 3, BLUE)).as("nothing above 1.6 m").isZero();
        assertThat(before.countNear(new Vec3(0.45, 0.45, 0), 3, RED)).as("nothing beside the block").isZero();
        assertThat(before.countNear(new Vec3(-0.45, 0.45, 0), 3, RED)).as("nothing beside the block").isZero();
    }

    @Test
    void itsTimeSensorTiltsTheHead() {
        // Mid-nod the head (0.36 m wide, 0.71 m tall, centred 1.24 m up) is tipped 0.8 rad: its point 0.1 m
        // out from its axis and 0.28 m up it is 0.27 m to one side, well beyond the upright head's 0.18 m.
        Vec3 right = new Vec3(0.27, 1.367, 0);
        Vec3 left = new Vec3(-0.27, 1.367, 0);
        int beside = during.countNear(right, 2, BLUE) + during.countNear(left, 2, BLUE);
        int besideBefore = before.countNear(right, 2, BLUE) + before.countNear(left, 2, BLUE);
        assertThat(besideBefore).as("nothing beside the head before").isZero();
        assertThat(beside).as("head tipped over during").isEqualTo(25);
        assertThat(before.differences(during, 40, i -> true)).as("pixels changed").isGreaterThan(300);
    }

    @Test
    void asAuthoredItStandsWhereItsAuthorPutIt() {
        assertThat(asAuthored.countNear(new Vec3(0, 0.45, 0), 3, RED)).as("nothing at the agent's place").isZero();
        assertThat(asAuthored.countNear(new Vec3(0, 1.25, 0), 3, BLUE)).as("nothing at the agent's place").isZero();
    }
}
