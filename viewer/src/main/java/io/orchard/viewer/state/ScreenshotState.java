package io.orchard.viewer.state;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.post.SceneProcessor;
import com.jme3.profile.AppProfiler;
import com.jme3.renderer.RenderManager;
import com.jme3.renderer.ViewPort;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.texture.FrameBuffer;
import com.jme3.texture.Image;
import com.jme3.texture.Texture2D;
import com.jme3.texture.image.ColorSpace;
import com.jme3.util.BufferUtils;
import io.orchard.viewer.world.WorldMirror;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;

/**
 * Headless screenshots. The scene and the panels are rendered into an off-screen frame buffer
 * whose colour target is an sRGB texture (so the colours come out as on a screen), and when the
 * clock reaches a shot's time, with the world shown and every agent's model in place, the frame is
 * read back and written as a PNG. Replaying a recording, the clock is moved straight to each
 * shot's time ({@link ReplayState#advanceTo}), so the same recording and shots give the same
 * images; with a live server the shot waits for the server's clock.
 *
 * <p>When the last shot is written the run finishes. A live game that ends first has its
 * remaining listed shots taken of its final state; with a shot every so many seconds, it gets one
 * more, of its final state ({@link ShotPlan#finalShot}).
 */
public final class ScreenshotState extends BaseAppState {

    private final ShotPlan plan;
    private final WorldMirror mirror;
    private final SimClock clock;
    private final ReplayState replay;
    private final RunControl control;
    private FrameBuffer target;
    private ByteBuffer pixels;
    private Shot armed;
    private boolean done;
    private boolean finalShotTaken;
    private final Capture capture = new Capture();
    private int width;
    private int height;

    /**
     * Takes the shots of {@code plan} of the world of {@code mirror} at the times of {@code clock}, and ends
     * the run through {@code control} after the last.
     *
     * @param replay the replay whose clock this state moves, or null for a live server
     */
    public ScreenshotState(ShotPlan plan, WorldMirror mirror, SimClock clock, ReplayState replay, RunControl control) {
        this.plan = plan;
        this.mirror = mirror;
        this.clock = clock;
        this.replay = replay;
        this.control = control;
    }

    @Override
    protected void initialize(Application app) {
        width = app.getCamera().getWidth();
        height = app.getCamera().getHeight();
        Texture2D color = new Texture2D(width, height, Image.Format.RGBA8);
        color.getImage().setColorSpace(ColorSpace.sRGB);
        target = new FrameBuffer(width, height, 1);
        target.addColorTarget(FrameBuffer.FrameBufferTarget.newTarget(color));
        target.setDepthTarget(FrameBuffer.FrameBufferTarget.newTarget(Image.Format.Depth));
        target.setSrgb(true);
        target.setName("screenshot");
        app.getViewPort().setOutputFrameBuffer(target);
        app.getGuiViewPort().setOutputFrameBuffer(target);
        app.getGuiViewPort().addProcessor(capture);
        pixels = BufferUtils.createByteBuffer(width * height * 4);
    }

    /** Whether every shot has been written. */
    public boolean isDone() {
        return done;
    }

    @Override
    public void update(float tpf) {
        if (done || armed != null) {
            return;
        }
        Shot next = plan.next();
        if (next == null) {
            finish();
            return;
        }
        if (!mirror.hasWorld()) {
            return;
        }
        boolean over = mirror.gameOver().isPresent();
        if (replay != null) {
            replay.advanceTo(next.time());
        } else if (over && plan.isPeriodic() && clock.now() < next.time()) {
            // The game ended before this shot's time: nothing more will happen but the final
            // picture, which is what a teacher shows at the end of a match.
            if (finalShotTaken) {
                finish();
                return;
            }
            next = plan.finalShot(clock.now());
        }
        AgentsState agents = getState(AgentsState.class);
        boolean settled = agents == null || agents.isSettled();
        if (settled && (clock.now() >= next.time() - 1e-9 || (replay == null && over))) {
            armed = next;
            finalShotTaken |= over && replay == null && plan.isPeriodic();
        }
    }

    /** Reads the frame back once it is rendered, panels included (the GUI viewport renders last). */
    private void captured(RenderManager renderManager) {
        if (armed == null) {
            return;
        }
        Shot shot = armed;
        armed = null;
        pixels.clear();
        renderManager.getRenderer().readFrameBuffer(target, pixels);
        try {
            write(shot.file());
        } catch (IOException | RuntimeException e) {
            control.failed("cannot write screenshot " + shot.file() + ": " + e.getMessage());
            done = true;
            return;
        }
        plan.taken();
        double since = (System.currentTimeMillis() - ManagementFactory.getRuntimeMXBean().getStartTime()) / 1000.0;
        control.report(String.format(Locale.ROOT, "wrote %s (%dx%d, t=%.2f s, %d agents, %.2f s after start)",
                shot.file(), width, height, clock.now(), mirror.agents().size(), since));
    }

    private void write(Path file) throws IOException {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            int row = (height - 1 - y) * width * 4; // GL rows run bottom-up
            for (int x = 0; x < width; x++) {
                int at = row + x * 4;
                int r = pixels.get(at) & 0xff;
                int g = pixels.get(at + 1) & 0xff;
                int b = pixels.get(at + 2) & 0xff;
                image.setRGB(x, y, (r << 16) | (g << 8) | b);
            }
        }
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        if (!ImageIO.write(image, "png", file.toFile())) {
            throw new IOException("no PNG writer available");
        }
    }

    private void finish() {
        done = true;
        control.finished(plan.count() + " screenshot(s) written");
    }

    @Override
    protected void cleanup(Application app) {
        app.getGuiViewPort().removeProcessor(capture);
    }

    @Override
    protected void onEnable() {
    }

    @Override
    protected void onDisable() {
    }

    /** The hook at the end of the GUI viewport's frame. */
    private final class Capture implements SceneProcessor {

        private RenderManager renderManager;

        @Override
        public void initialize(RenderManager rm, ViewPort vp) {
            renderManager = rm;
        }

        @Override
        public void reshape(ViewPort vp, int w, int h) {
        }

        @Override
        public boolean isInitialized() {
            return renderManager != null;
        }

        @Override
        public void preFrame(float tpf) {
        }

        @Override
        public void postQueue(RenderQueue rq) {
        }

        @Override
        public void postFrame(FrameBuffer out) {
            captured(renderManager);
        }

        @Override
        public void cleanup() {
            renderManager = null;
        }

        @Override
        public void setProfiler(AppProfiler profiler) {
        }
    }
}
