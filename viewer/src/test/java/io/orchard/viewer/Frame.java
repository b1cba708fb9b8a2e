package io.orchard.viewer;

import com.jme3.math.Vector3f;
import com.jme3.renderer.Camera;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.state.CameraState;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import java.util.function.IntPredicate;
import javax.imageio.ImageIO;

/**
 * A screenshot read back, with the camera that took it, to find where a point of the world is in
 * the picture and what colours lie around it. Comparisons use tolerances: colours by which channel
 * dominates, positions within a few pixels.
 */
final class Frame {

    final BufferedImage image;
    private final Camera camera;

    private Frame(BufferedImage image, Camera camera) {
        this.image = image;
        this.camera = camera;
    }

    /** Reads a PNG taken with the viewer's lens from {@code location} looking at {@code target}. */
    static Frame read(Path png, Vec3 location, Vec3 target) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        if (image == null) {
            throw new AssertionError(png + " is not a readable image");
        }
        Camera camera = CameraState.lens(image.getWidth(), image.getHeight());
        camera.setLocation(vector(location));
        camera.lookAt(vector(target), Vector3f.UNIT_Y);
        camera.update();
        return new Frame(image, camera);
    }

    /** Where a world point shows, in image pixels (x right, y down). */
    int[] pixelOf(Vec3 world) {
        Vector3f screen = camera.getScreenCoordinates(vector(world));
        return new int[] {Math.round(screen.x), image.getHeight() - 1 - Math.round(screen.y)};
    }

    /** The colour at a pixel as {r, g, b}. */
    int[] rgb(int x, int y) {
        int c = image.getRGB(x, y);
        return new int[] {(c >> 16) & 0xff, (c >> 8) & 0xff, c & 0xff};
    }

    /** How many pixels within {@code radius} of where {@code world} shows have a colour the test accepts. */
    int countNear(Vec3 world, int radius, ColorTest test) {
        int[] p = pixelOf(world);
        int count = 0;
        for (int y = Math.max(0, p[1] - radius); y <= Math.min(image.getHeight() - 1, p[1] + radius); y++) {
            for (int x = Math.max(0, p[0] - radius); x <= Math.min(image.getWidth() - 1, p[0] + radius); x++) {
                int[] c = rgb(x, y);
                if (test.accepts(c[0], c[1], c[2])) {
                    count++;
                }
            }
        }
        return count;
    }

    /** How many pixels near where {@code world} shows differ from {@code reference} by more than {@code tolerance}. */
    int countUnlike(Vec3 world, int radius, int[] reference, int tolerance) {
        return countNear(world, radius, (r, g, b) -> Math.abs(r - reference[0]) > tolerance
                || Math.abs(g - reference[1]) > tolerance || Math.abs(b - reference[2]) > tolerance);
    }

    /** How many distinct colours the picture has, counted at 5 bits a channel. */
    int distinctColours() {
        Set<Integer> seen = new HashSet<>();
        for (int y = 0; y < image.getHeight(); y += 2) {
            for (int x = 0; x < image.getWidth(); x += 2) {
                seen.add((image.getRGB(x, y) >> 3) & 0x1f1f1f);
            }
        }
        return seen.size();
    }

    /** How many pixels, among those {@code whereIndex} allows, differ from {@code other}'s by more than {@code tolerance}. */
    int differences(Frame other, int tolerance, IntPredicate whereIndex) {
        int count = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                if (!whereIndex.test(y * image.getWidth() + x)) {
                    continue;
                }
                int[] a = rgb(x, y);
                int[] b = other.rgb(x, y);
                if (Math.abs(a[0] - b[0]) > tolerance || Math.abs(a[1] - b[1]) > tolerance
                        || Math.abs(a[2] - b[2]) > tolerance) {
                    count++;
                }
            }
        }
        return count;
    }

    int width() {
        return image.getWidth();
    }

    int height() {
        return image.getHeight();
    }

    private static Vector3f vector(Vec3 v) {
        return new Vector3f((float) v.x(), (float) v.y(), (float) v.z());
    }

    /** A test on a colour. */
    @FunctionalInterface
    interface ColorTest {
        boolean accepts(int r, int g, int b);

        /** Grass and meadow: green well above red and blue. */
        ColorTest GREEN = (r, g, b) -> g > r + 20 && g > b + 40;
        /** Water: blue well above red and green. */
        ColorTest BLUE = (r, g, b) -> b > r + 60 && b > g + 20;
        /** Stone: bright, and no channel far from the others. */
        ColorTest STONE = (r, g, b) -> r > 90 && Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b)) < 60;
        /** A tomato: strongly red. */
        ColorTest RED = (r, g, b) -> r > 120 && r > 2 * g && r > 2 * b;
        /** A coconut: a dark brown, red above green above blue. */
        ColorTest BROWN = (r, g, b) -> r > g && g > b && r < 170 && r - b > 25;
        /** The bundled figure's shirt: purple, red and blue both well above green. */
        ColorTest PURPLE = (r, g, b) -> b > g + 40 && r > g + 20;
    }
}
