package io.orchard.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.model.SplitBlock;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@link SplitBlock}, a glTF in centimetres with its origin off its centre, its buffer and its
 * texture files of their own, sent as a zip and registered through a live server at the origin
 * with a body 1.6 m tall: it stands there 1.6 m tall and 0.4 m wide, in its texture's magenta.
 */
class HeadlessZipModelTest {

    static final Vec3 CAMERA = new Vec3(0, 1.2, 5);
    static final Vec3 TARGET = new Vec3(0, 1, 0);
    static final Frame.ColorTest MAGENTA = (r, g, b) -> r > g + 60 && b > g + 60;

    @TempDir
    static Path dir;
    static ViewerProcess.Result shots;
    static Frame frame;

    @BeforeAll
    static void playAndTakeTheScreenshot() throws Exception {
        ViewerProcess.xvfbRun();
        Path recording = GameFixture.posing(dir, SplitBlock.NAME, ModelSpec.of(ModelFormat.ZIP, SplitBlock.zip()),
                List.of(), Map.of(), 1);
        shots = ViewerProcess.run(dir, false, "--replay", recording.toString(), "--headless", "--size", "640x360",
                "--hud", "off", "--camera", "0,1.2,5", "--look-at", "0,1,0", "--screenshot", "block.png", "--at", "0.5");
        assertThat(shots.exit()).as("exit status; output:%n%s", shots.output()).isZero();
        // Kept for a person to look at.
        Files.copy(dir.resolve("block.png"), Path.of("target", "zipped-block.png"), StandardCopyOption.REPLACE_EXISTING);
        frame = Frame.read(dir.resolve("block.png"), CAMERA, TARGET);
    }

    @Test
    void theModelLoadsWithoutAProblem() {
        assertThat(shots.output()).doesNotContain("placeholder", "cannot be shown", "not fetched");
    }

    @Test
    void itStandsWhereTheAgentIsAtTheBodysSizeInItsTexturesColour() {
        assertThat(frame.countNear(new Vec3(0, 0.2, 0), 3, MAGENTA)).as("low").isEqualTo(49);
        assertThat(frame.countNear(new Vec3(0, 1.5, 0), 3, MAGENTA)).as("high").isEqualTo(49);
        assertThat(frame.countNear(new Vec3(0, 1.75, 0), 3, MAGENTA)).as("nothing above 1.6 m").isZero();
        assertThat(frame.countNear(new Vec3(0.32, 0.8, 0), 3, MAGENTA)).as("nothing beside it").isZero();
        assertThat(frame.countNear(new Vec3(-0.32, 0.8, 0), 3, MAGENTA)).as("nothing beside it").isZero();
    }
}
