package io.orchard.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.replay.Recording;
import io.orchard.viewer.world.WorldMirror;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Screenshots of the scripted game, taken by the headless viewer from its recording, as a child
 * JVM under Xvfb with Mesa's software OpenGL. The camera is fixed, so the test projects points of
 * the world with the viewer's own lens and checks the colours found there: the ground, the river,
 * the castle, the fruit, the walking agent (at its place at each time, having moved between the
 * two shots) and the coconut it ate (gone from the later shot).
 */
class HeadlessReplayTest {

    static final Vec3 CAMERA = new Vec3(18, 22, 26);
    static final Vec3 TARGET = new Vec3(-2, 0, -6);
    static final double EARLY = 0.5;
    static final double LATE = 2.25;

    @TempDir
    static Path dir;
    static Path recording;
    static ViewerProcess.Result shots;
    static ViewerProcess.Result periodic;
    static Frame early;
    static Frame late;

    @BeforeAll
    static void takeTheScreenshots() throws Exception {
        ViewerProcess.xvfbRun();
        recording = GameFixture.sharedScripted();
        String[] view = {"--replay", recording.toString(), "--headless", "--size", "960x540", "--hud", "off",
            "--camera", "18,22,26", "--look-at", "-2,0,-6"};
        shots = ViewerProcess.run(dir, concat(view, "--screenshot", "early.png", "--at", "0.5",
                "--screenshot", "late.png", "--at", "2.25"));
        assertThat(shots.exit()).as("exit status; output:%n%s", shots.output()).isZero();
        periodic = ViewerProcess.run(dir, concat(view, "--every", "0.25", "--until", "2.25", "--out", "frames"));
        early = Frame.read(dir.resolve("early.png"), CAMERA, TARGET);
        late = Frame.read(dir.resolve("late.png"), CAMERA, TARGET);
    }

    @Test
    void eachScreenshotIsReportedWithItsTime() {
        assertThat(shots.output()).contains("wrote early.png (960x540, t=0.50 s, 2 agents",
                "wrote late.png (960x540, t=2.25 s, 2 agents");
    }

    @Test
    void theScreenshotIsNotBlank() {
        assertThat(early.distinctColours()).isGreaterThan(60);
    }

    @Test
    void groundRiverCastleAndFruitAreWhereTheCameraPutsThem() {
        for (Vec3 grass : List.of(new Vec3(0, 0, -15), new Vec3(8, 0, 2), new Vec3(-8, 0, 0))) {
            assertThat(early.countNear(grass, 2, Frame.ColorTest.GREEN)).as("grass at %s", grass).isEqualTo(25);
        }
        for (Vec3 water : List.of(new Vec3(0, 0.06, 11), new Vec3(-20, 0.06, 11), new Vec3(8, 0.06, 10))) {
            assertThat(early.countNear(water, 2, Frame.ColorTest.BLUE)).as("water at %s", water).isEqualTo(25);
        }
        Vec3 castleRoof = new Vec3(-21, 7, -22);
        assertThat(early.countNear(castleRoof, 2, Frame.ColorTest.STONE)).as("castle stone").isGreaterThan(20);
        assertThat(early.countNear(new Vec3(-1, 0.15, -3), 3, Frame.ColorTest.RED)).as("tomato F2").isPositive();
        assertThat(early.countNear(new Vec3(4, 0.35, -6), 3, Frame.ColorTest.BROWN)).as("coconut F1").isPositive();
    }

    @Test
    void theWalkerIsDrawnWhereItIsAtEachTimeAndMovesBetweenThem() throws Exception {
        Vec3 thenAt = walkerChest(EARLY);
        Vec3 laterAt = walkerChest(LATE);
        assertThat(thenAt.x()).as("walking north to the coconut").isEqualTo(4);
        assertThat(laterAt.x()).as("walking east after it").isGreaterThan(6);

        assertThat(early.countNear(thenAt, 4, Frame.ColorTest.PURPLE)).as("shirt at %s early", thenAt).isPositive();
        assertThat(late.countNear(thenAt, 4, Frame.ColorTest.PURPLE)).as("shirt at %s late", thenAt).isZero();
        assertThat(late.countNear(laterAt, 4, Frame.ColorTest.PURPLE)).as("shirt at %s late", laterAt).isPositive();
        assertThat(early.countNear(laterAt, 4, Frame.ColorTest.PURPLE)).as("shirt at %s early", laterAt).isZero();
    }

    @Test
    void theEatenCoconutIsGoneFromTheLaterShot() {
        Vec3 coconut = new Vec3(4, 0.35, -6);
        assertThat(early.countNear(coconut, 3, Frame.ColorTest.BROWN)).isPositive();
        assertThat(late.countNear(coconut, 3, Frame.ColorTest.BROWN)).isZero();
        assertThat(late.countNear(new Vec3(-1, 0.15, -3), 3, Frame.ColorTest.RED)).as("the tomato stays").isPositive();
    }

    @Test
    void betweenTheShotsOnlyTheWalkerAndTheCoconutChange() throws Exception {
        List<int[]> moving = List.of(early.pixelOf(walkerChest(EARLY)), early.pixelOf(walkerChest(LATE)),
                early.pixelOf(walkerChest(1.2)), early.pixelOf(new Vec3(4, 0.35, -6)));
        int width = early.width();
        int elsewhere = early.differences(late, 40, index -> moving.stream().noneMatch(p ->
                Math.abs(index % width - p[0]) < 45 && Math.abs(index / width - p[1]) < 45));
        assertThat(elsewhere).as("pixels changed away from the walker and the coconut")
                .isLessThan(early.width() * early.height() / 500);
    }

    @Test
    void aModelThatFailsToLoadShowsAsAPlaceholderAndTheViewerSaysWhy() {
        assertThat(shots.output()).contains("agent Broken: its x3d model cannot be shown, a placeholder stands in");
        Vec3 broken = new Vec3(GameFixture.BROKEN_AT.x(), 0.8, GameFixture.BROKEN_AT.z());
        int[] at = early.pixelOf(broken);
        int[] grass = early.rgb(at[0] - 40, at[1]);
        assertThat(early.countUnlike(broken, 3, grass, 40)).as("pixels unlike the grass beside Broken")
                .isGreaterThan(30);
    }

    @Test
    void theSameRecordingGivesTheSameFramesHoweverTheClockSteps() throws Exception {
        assertThat(periodic.exit()).as("exit status; output:%n%s", periodic.output()).isZero();
        try (var files = Files.list(dir.resolve("frames"))) {
            assertThat(files.map(f -> f.getFileName().toString()).sorted().toList()).hasSize(10)
                    .startsWith("t0000.00.png", "t0000.25.png").endsWith("t0002.25.png");
        }
        Frame stepped = Frame.read(dir.resolve("frames/t0000.50.png"), CAMERA, TARGET);
        Frame steppedLate = Frame.read(dir.resolve("frames/t0002.25.png"), CAMERA, TARGET);
        int pixels = early.width() * early.height();
        assertThat(early.differences(stepped, 3, i -> true)).as("pixels that differ at 0.5 s").isLessThan(pixels / 1000);
        assertThat(late.differences(steppedLate, 3, i -> true)).as("pixels that differ at 2.25 s")
                .isLessThan(pixels / 1000);
    }

    /** Where the walker's shirt is at {@code time}, by the recording. */
    private static Vec3 walkerChest(double time) throws Exception {
        WorldMirror mirror = new WorldMirror();
        for (Recording.Entry entry : Recording.read(recording).entries()) {
            if (entry.time() <= time) {
                mirror.apply(entry.message(), entry.time());
            }
        }
        Vec3 feet = mirror.agent("Walker").orElseThrow().positionAt(time);
        return new Vec3(feet.x(), 1.15, feet.z());
    }

    private static String[] concat(String[] first, String... rest) {
        String[] all = new String[first.length + rest.length];
        System.arraycopy(first, 0, all, 0, first.length);
        System.arraycopy(rest, 0, all, first.length, rest.length);
        return all;
    }
}
