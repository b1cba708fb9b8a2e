package io.orchard.examples.demo;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.orchard.examples.Orchard;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The demo plays a whole short match headless: the viewer (a child JVM under xvfb-run, as on a
 * machine without a screen) writes screenshots, and the ranking of the five agents comes last.
 */
class DemoCommandTest {

    @TempDir
    Path dir;

    @Test
    void aShortHeadlessDemoWritesScreenshotsAndEndsWithTheRanking() throws Exception {
        assumeTrue(DemoCommand.hasDisplay() || HeadlessViewer.xvfbRun() != null,
                "the headless viewer needs a display or xvfb-run (apt-get install xvfb xauth; .ci/run does this)");
        Path shots = dir.resolve("shots");
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);

        int status = Orchard.run(new String[] {"demo", "--headless", "--time-limit", "4", "--seed", "1998", "--out",
                shots.toString()}, out, out);

        String printed = bytes.toString(StandardCharsets.UTF_8);
        assertThat(status).as(printed).isZero();
        assertThat(printed).contains("Orchard demo: seed 1998, server on port ", "The game starts.",
                "Game over (time limit reached). Ranking:");
        List<String> lines = printed.lines().toList();
        assertThat(lines.subList(lines.size() - 5, lines.size())).as(printed)
                .allMatch(line -> line.matches(" +[1-5]\\. (Dwarf|Robot|Bunny|Guppy|Roadrunner) .*"));
        List<Path> pictures;
        try (Stream<Path> files = Files.list(shots)) {
            pictures = files.filter(file -> file.toString().endsWith(".png")).toList();
        }
        assertThat(pictures).as(printed).isNotEmpty().contains(shots.resolve("t0000.00.png"));
        // The game ends between two shots (4 s, a shot every 10 s): the last picture is its final state.
        assertThat(pictures).as(printed).anyMatch(file -> file.getFileName().toString().matches("t\\d{4}\\.\\d\\d-final\\.png"));
        assertThat(printed).as("the final picture shows where the five agents ended")
                .containsPattern("-final\\.png \\(1280x720, t=[0-9.]+ s, 5 agents");
        BufferedImage first = ImageIO.read(shots.resolve("t0000.00.png").toFile());
        assertThat(first.getWidth()).isEqualTo(1280);
        assertThat(first.getHeight()).isEqualTo(720);
    }

    @Test
    void withWebTheDemoPrintsTheAddressOfTheBrowserViewerWhichServesThePage() throws Exception {
        assumeTrue(DemoCommand.hasDisplay() || HeadlessViewer.xvfbRun() != null,
                "the headless viewer needs a display or xvfb-run (apt-get install xvfb xauth; .ci/run does this)");
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        CompletableFuture<Integer> status = CompletableFuture.supplyAsync(() -> Orchard.run(new String[] {"demo",
                "--headless", "--web", "--time-limit", "4", "--seed", "1998", "--out", dir.resolve("shots").toString()},
                out, out));

        Pattern address = Pattern.compile("In a browser: (http://127\\.0\\.0\\.1:\\d+/) \\(operator token for the"
                + " page: [0-9a-f]{32}\\)");
        Matcher printed = address.matcher("");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!printed.reset(bytes.toString(StandardCharsets.UTF_8)).find() && !status.isDone()
                && System.nanoTime() < deadline) {
            Thread.sleep(50);
        }
        assertThat(printed.reset(bytes.toString(StandardCharsets.UTF_8)).find()).as(bytes.toString(
                StandardCharsets.UTF_8)).isTrue();
        HttpResponse<String> page = HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create(printed.group(1)))
                .build(), HttpResponse.BodyHandlers.ofString());
        assertThat(page.statusCode()).isEqualTo(200);
        assertThat(page.body()).contains("<canvas id=\"world\"");
        assertThat(status.get(3, TimeUnit.MINUTES)).as(bytes.toString(StandardCharsets.UTF_8)).isZero();
    }

    @Test
    void aTimeLimitThatIsNotANumberIsAUsageErrorNamingIt() {
        assertThat(usageError("--time-limit", "soon")).contains("orchard demo: invalid value for option "
                + "'--time-limit': 'soon' is not a number (expected 1-86400 seconds)");
    }

    @Test
    void aSeedThatIsNotAWholeNumberIsAUsageErrorNamingIt() {
        assertThat(usageError("--seed", "1.5"))
                .contains("orchard demo: invalid value for option '--seed': '1.5' is not an integer");
    }

    /** What {@code ./orchard demo args} prints on standard error, once it has exited with status 2. */
    private static String usageError(String... args) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        String[] line = Stream.concat(Stream.of("demo"), Stream.of(args)).toArray(String[]::new);
        PrintStream none = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);

        assertThat(Orchard.run(line, none, new PrintStream(err, true, StandardCharsets.UTF_8))).isEqualTo(2);
        return err.toString(StandardCharsets.UTF_8);
    }
}
