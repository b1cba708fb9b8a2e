package io.orchard.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.StartAnimationMessage;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.model.SkinnedFigure;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.LongFunction;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A glTF figure authored for the tests ({@link SkinnedFigure}) registered through a live server
 * at the origin, facing north (so the model's +x is the world's -x), fitted to its body, its named skinned clip
 * {@code Wave.Arm} and its unnamed clip {@code clip#1} started by the agent at 0.5 s; screenshots
 * of the recording before and 0.5 s after: the skinned upper body has bent over to the side and
 * the flag has risen, and nothing of them is left where they were. The viewer runs without
 * {@code XDG_RUNTIME_DIR}, as on a bare machine, and says nothing of it.
 */
class HeadlessModelTest {

    static final Vec3 CAMERA = new Vec3(0, 1.2, 5);
    static final Vec3 TARGET = new Vec3(0, 1, 0);
    /** The figure's orange body: red well above green, green well above blue. */
    static final Frame.ColorTest ORANGE = (r, g, b) -> r > 120 && r > g + 40 && g > b + 40;
    /** The flag: green and blue well above red. */
    static final Frame.ColorTest CYAN = (r, g, b) -> b > r + 60 && g > r + 60;

    // Fitted to the body, 1.6 m as authored: centred on the 1 m from its left side to its flag.
    static final Vec3 CHEST = new Vec3(0.25, 1.4, 0);
    static final Vec3 BENT_CHEST = new Vec3(0.75, 0.8, 0);
    static final Vec3 FLAG_LOW = new Vec3(-0.35, 1.2, 0);
    static final Vec3 FLAG_HIGH = new Vec3(-0.35, 2.0, 0);

    @TempDir
    static Path dir;
    static ViewerProcess.Result shots;
    static Frame before;
    static Frame during;

    @BeforeAll
    static void playAndTakeTheScreenshots() throws Exception {
        ViewerProcess.xvfbRun();
        Map<Long, List<LongFunction<ClientMessage>>> script = new HashMap<>();
        GameFixture.at(script, 10, seq -> new StartAnimationMessage(seq, "Figure", SkinnedFigure.WAVE, true));
        GameFixture.at(script, 10, seq -> new StartAnimationMessage(seq, "Figure", "clip#1", true));
        Path recording = GameFixture.posing(dir, "Figure", ModelSpec.of(ModelFormat.GLTF, SkinnedFigure.embedded()),
                List.of(SkinnedFigure.WAVE, "clip#1"), script, 2);
        shots = ViewerProcess.run(dir, false, "--replay", recording.toString(), "--headless", "--size", "640x360",
                "--hud", "off", "--camera", "0,1.2,5", "--look-at", "0,1,0",
                "--screenshot", "before.png", "--at", "0.4", "--screenshot", "during.png", "--at", "1.0");
        assertThat(shots.exit()).as("exit status; output:%n%s", shots.output()).isZero();
        // Kept for a person to look at: target/skinned-*.png.
        for (String shot : List.of("before", "during")) {
            java.nio.file.Files.copy(dir.resolve(shot + ".png"), Path.of("target", "skinned-" + shot + ".png"),
                    java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        before = Frame.read(dir.resolve("before.png"), CAMERA, TARGET);
        during = Frame.read(dir.resolve("during.png"), CAMERA, TARGET);
    }

    @Test
    void theModelLoadsWithoutAProblem() {
        assertThat(shots.output()).doesNotContain("placeholder", "cannot be shown");
    }

    @Test
    void aRunWithoutARuntimeFolderPrintsNoNoiseOfTheLibraries() {
        assertThat(shots.output()).doesNotContain("XDG_RUNTIME_DIR", "OGGLoader", "Cannot find loader");
    }

    @Test
    void theSkinnedUpperBodyBendsWhileItsNamedClipPlays() {
        assertThat(before.countNear(CHEST, 3, ORANGE)).as("chest upright before").isEqualTo(49);
        assertThat(before.countNear(BENT_CHEST, 3, ORANGE)).as("nothing beside the hips before").isZero();
        assertThat(during.countNear(BENT_CHEST, 3, ORANGE)).as("chest bent over during").isEqualTo(49);
        assertThat(during.countNear(CHEST, 3, ORANGE)).as("nothing upright during").isZero();
    }

    @Test
    void theFlagRisesWhileItsUnnamedClipPlays() {
        assertThat(before.countNear(FLAG_LOW, 3, CYAN)).as("flag low before").isEqualTo(49);
        assertThat(during.countNear(FLAG_HIGH, 3, CYAN)).as("flag high during").isEqualTo(49);
        assertThat(during.countNear(FLAG_LOW, 3, CYAN)).as("flag gone from low during").isZero();
    }

    @Test
    void onlyTheAnimatedPartsChangeTheFrame() {
        int changed = before.differences(during, 40, i -> true);
        assertThat(changed).as("pixels changed").isGreaterThan(2000).isLessThan(before.width() * before.height() / 10);
    }
}
