package io.orchard.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import com.jme3.math.ColorRGBA;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.FruitState;
import io.orchard.viewer.model.BodyModels;
import io.orchard.viewer.scene.Palette;
import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The default view of a game of five agents at 1280x720, the panels on, as a newcomer sees it: each
 * agent shows at least 20 pixels tall (its pin, in its colour) with its name in text at least 12
 * pixels tall above it, each fruit as a dot of at least 6 pixels in its kind's colour, and the game
 * panel keeps to the left quarter of the frame, the world framed beside it.
 */
class HeadlessSeeingTest {

    private static final int AGENTS = 5;

    @TempDir
    static Path dir;
    static BufferedImage shot;
    static List<FruitState> fruit;

    @BeforeAll
    static void playAndTakeTheScreenshot() throws Exception {
        ViewerProcess.xvfbRun();
        Path recording = GameFixture.crowd(dir, AGENTS, 3);
        ViewerProcess.Result run = ViewerProcess.run(dir, false, "--replay", recording.toString(), "--headless",
                "--size", "1280x720", "--screenshot", "default.png", "--at", "2");
        assertThat(run.exit()).as("exit status; output:%n%s", run.output()).isZero();
        Files.copy(dir.resolve("default.png"), Path.of("target", "default-view.png"), StandardCopyOption.REPLACE_EXISTING);
        shot = ImageIO.read(dir.resolve("default.png").toFile());
        MessageCodec codec = new MessageCodec();
        for (String line : Files.readAllLines(recording, StandardCharsets.UTF_8)) {
            int start = line.indexOf("{\"type\":\"WorldSnapshot\"");
            if (start >= 0) {
                ServerMessage snapshot = codec.decodeServer(line.substring(start, line.lastIndexOf('}')));
                fruit = ((WorldSnapshotMessage) snapshot).fruit();
                break;
            }
        }
        assertThat(fruit).as("the world's fruit").isNotEmpty();
    }

    @Test
    void eachAgentShowsAtLeast20PixelsTallWithItsNameInTextAtLeast12PixelsTall() {
        List<int[]> pins = new ArrayList<>();
        for (int i = 0; i < AGENTS; i++) {
            String name = "Agent" + i;
            ColorRGBA colour = BodyModels.colourOf(name);
            // The pin is drawn in the agent's colour as sRGB, exactly.
            int[] pin = tallestRun(new int[] {Math.round(colour.r * 255), Math.round(colour.g * 255),
                Math.round(colour.b * 255)});
            assertThat(pin[2]).as("%s: the tallest run of its colour, in pixels", name).isGreaterThanOrEqualTo(20);
            assertThat(pins).as("%s: its pin is not another's", name)
                    .noneMatch(other -> Math.abs(other[0] - pin[0]) < 3 && Math.abs(other[1] - pin[1]) < 3);
            pins.add(pin);
            int text = textHeightAbove(pin[0], pin[1]);
            // From the top of its capitals to the foot of its descenders.
            assertThat(text).as("%s: the height of its name's letters, in pixels", name).isGreaterThanOrEqualTo(12);
        }
    }

    @Test
    void eachKindOfFruitShowsAsDotsOfItsOwnColourAtLeast6PixelsWide() {
        Map<FruitKind, Integer> expected = new EnumMap<>(FruitKind.class);
        fruit.forEach(f -> expected.merge(f.kind(), 1, Integer::sum));
        int dots = 0;
        for (Map.Entry<FruitKind, Integer> kind : expected.entrySet()) {
            int found = blocks(srgb(colour(kind.getKey())), 6);
            assertThat(found).as("dots of %s, of %d", kind.getKey(), kind.getValue()).isPositive();
            dots += found;
        }
        // Fruit on one table, or hanging from one tree, may show as one dot.
        assertThat(dots).as("dots of %d fruit", fruit.size()).isGreaterThanOrEqualTo(fruit.size() / 2);
    }

    @Test
    void theGamePanelKeepsToTheLeftQuarter() {
        int[] back = rgb(3, 40);
        int right = 0;
        for (int x = 0; x < shot.getWidth(); x++) {
            if (close(rgb(x, 40), back, 4) || close(rgb(x, 45), back, 4)) {
                right = x;
            }
        }
        assertThat(right).as("the panel's right edge").isBetween(100, shot.getWidth() / 4);
    }

    private static ColorRGBA colour(FruitKind kind) {
        return switch (kind) {
            case TOMATO -> Palette.TOMATO;
            case BANANA -> Palette.BANANA;
            case COCONUT -> Palette.COCONUT;
        };
    }

    /** A linear colour as an sRGB frame shows it. */
    private static int[] srgb(ColorRGBA linear) {
        ColorRGBA shown = linear.getAsSrgb();
        return new int[] {Math.round(shown.r * 255), Math.round(shown.g * 255), Math.round(shown.b * 255)};
    }

    private int[] rgb(int x, int y) {
        int c = shot.getRGB(x, y);
        return new int[] {(c >> 16) & 0xff, (c >> 8) & 0xff, c & 0xff};
    }

    private static boolean close(int[] a, int[] b, int tolerance) {
        return Math.abs(a[0] - b[0]) <= tolerance && Math.abs(a[1] - b[1]) <= tolerance
                && Math.abs(a[2] - b[2]) <= tolerance;
    }

    /** The column, the top row and the length of the tallest vertical run of a colour. */
    private int[] tallestRun(int[] colour) {
        int[] best = {0, 0, 0};
        for (int x = 0; x < shot.getWidth(); x++) {
            int run = 0;
            for (int y = 0; y < shot.getHeight(); y++) {
                run = close(rgb(x, y), colour, 6) ? run + 1 : 0;
                if (run > best[2]) {
                    best = new int[] {x, y - run + 1, run};
                }
            }
        }
        return best;
    }

    /**
     * The height of the tallest name within 80 rows above (x, top), 60 pixels either side: the
     * longest run of rows that have light letters' pixels (a name moved up past another's pin is
     * still the nearest block of letters above).
     */
    private int textHeightAbove(int x, int top) {
        int longest = 0;
        int run = 0;
        for (int y = Math.max(0, top - 80); y < top; y++) {
            boolean letters = false;
            for (int dx = -60; dx <= 60 && !letters; dx++) {
                int px = x + dx;
                letters = px >= 0 && px < shot.getWidth() && min(rgb(px, y)) >= 180;
            }
            run = letters ? run + 1 : 0;
            longest = Math.max(longest, run);
        }
        return longest;
    }

    private static int min(int[] c) {
        return Math.min(c[0], Math.min(c[1], c[2]));
    }

    /** How many separate squares of {@code side} pixels or more are all of a colour. */
    private int blocks(int[] colour, int side) {
        boolean[][] seen = new boolean[shot.getWidth()][shot.getHeight()];
        List<int[]> found = new ArrayList<>();
        for (int y = 0; y + side <= shot.getHeight(); y++) {
            for (int x = 0; x + side <= shot.getWidth(); x++) {
                if (seen[x][y] || !square(x, y, side, colour)) {
                    continue;
                }
                found.add(new int[] {x, y});
                for (int dy = -side; dy < 2 * side; dy++) {
                    for (int dx = -side; dx < 2 * side; dx++) {
                        if (x + dx >= 0 && y + dy >= 0 && x + dx < shot.getWidth() && y + dy < shot.getHeight()) {
                            seen[x + dx][y + dy] = true;
                        }
                    }
                }
            }
        }
        return found.size();
    }

    private boolean square(int x, int y, int side, int[] colour) {
        for (int dy = 0; dy < side; dy++) {
            for (int dx = 0; dx < side; dx++) {
                if (!close(rgb(x + dx, y + dy), colour, 10)) {
                    return false;
                }
            }
        }
        return true;
    }
}
