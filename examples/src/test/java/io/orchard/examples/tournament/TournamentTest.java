package io.orchard.examples.tournament;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.examples.Orchard;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A short tournament of three games writes its rows, its chart and its table. */
class TournamentTest {

    @TempDir
    static Path dir;
    static String printed;

    @BeforeAll
    static void playThreeShortGames() throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        int status = Orchard.run(new String[] {"tournament", "--games", "3", "--agents", "Roadrunner,Bunny,FirstAgent",
                "--seed-from", "40", "--time-limit", "15", "--out", dir.toString()}, out, out);
        printed = bytes.toString(StandardCharsets.UTF_8);
        assertThat(status).as(printed).isZero();
    }

    @Test
    void theSameSeedsGiveTheSameResults(@TempDir Path again) throws Exception {
        // Agents on their own threads race to connect and to act; in lockstep that must not show.
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        assertThat(Orchard.run(new String[] {"tournament", "--games", "3", "--agents", "Roadrunner,Bunny,FirstAgent",
                "--seed-from", "40", "--time-limit", "15", "--out", again.toString()}, out, out)).isZero();

        for (String file : List.of("results.csv", "results.json", "results.md")) {
            assertThat(Files.readAllBytes(again.resolve(file))).as(file)
                    .isEqualTo(Files.readAllBytes(dir.resolve(file)));
        }
    }

    @Test
    void theFiveAgentsPlayTheSameTwoGamesTwice(@TempDir Path first, @TempDir Path second) throws Exception {
        String[] printed = new String[2];
        Path[] dirs = {first, second};
        for (int run = 0; run < 2; run++) {
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
            assertThat(Orchard.run(new String[] {"tournament", "--games", "2", "--seed-from", "8",
                    "--time-limit", "30", "--out", dirs[run].toString()}, out, out)).isZero();
            printed[run] = bytes.toString(StandardCharsets.UTF_8);
        }

        assertThat(printed[0]).contains("Missed turns: none");
        assertThat(Files.readAllBytes(second.resolve("results.csv")))
                .isEqualTo(Files.readAllBytes(first.resolve("results.csv")));
        assertThat(Files.readAllLines(first.resolve("results.csv"), StandardCharsets.UTF_8)).hasSize(1 + 2 * 5);
    }

    @Test
    void theMarkdownHoldsARowPerGameAndOnePerAgent() throws Exception {
        List<String> lines = Files.readAllLines(dir.resolve("results.md"), StandardCharsets.UTF_8);

        assertThat(lines.get(0)).isEqualTo("| seed | fruit | collected together | Roadrunner | Bunny | FirstAgent "
                + "| moves refused by an obstacle | missed turns |");
        assertThat(lines.get(2)).matches("\\| 40 \\| \\d+ \\| \\d+ in \\d+ s \\| \\d+ \\| \\d+ \\| \\d+ \\| \\d+\\.\\d\\d % \\| 0 \\|");
        assertThat(lines).contains("| agent | games | fruit per game, mean | standard deviation | fewest | most "
                + "| points per game, mean |").anyMatch(line -> line.startsWith("| FirstAgent | 3 | "));
    }

    @Test
    void theCsvHasAHeaderAndOneRowPerAgentPerGame() throws Exception {
        List<String> lines = Files.readAllLines(dir.resolve("results.csv"), StandardCharsets.UTF_8);

        assertThat(lines).hasSize(1 + 3 * 3);
        assertThat(lines.get(0)).isEqualTo("game,seed,agent,fruit,points");
        assertThat(lines.get(1)).matches("1,40,Roadrunner,\\d+,\\d+");
        assertThat(lines.get(6)).matches("2,41,FirstAgent,\\d+,\\d+");
        assertThat(lines.get(9)).matches("3,42,FirstAgent,\\d+,\\d+");
    }

    @Test
    void theJsonHoldsTheSameRows() throws Exception {
        String json = Files.readString(dir.resolve("results.json"), StandardCharsets.UTF_8);

        assertThat(json.split("\"agent\"", -1)).hasSize(1 + 3 * 3);
        assertThat(json).startsWith("[").contains("{\"game\": 3, \"seed\": 42, \"agent\": \"Bunny\", \"fruit\": ")
                .contains("\"missedTurns\": []");
    }

    @Test
    void theChartIsAPictureOfTheExpectedSizeWithManyColours() throws Exception {
        BufferedImage chart = ImageIO.read(dir.resolve("chart.png").toFile());

        assertThat(chart).isNotNull();
        assertThat(chart.getWidth()).isEqualTo(FruitChart.WIDTH);
        assertThat(chart.getHeight()).isEqualTo(FruitChart.HEIGHT);
        Set<Integer> colours = new HashSet<>();
        int background = chart.getRGB(chart.getWidth() / 2, chart.getHeight() / 2);
        int drawn = 0;
        for (int y = 0; y < chart.getHeight(); y++) {
            for (int x = 0; x < chart.getWidth(); x++) {
                int rgb = chart.getRGB(x, y);
                colours.add(rgb);
                drawn += rgb != background ? 1 : 0;
            }
        }
        assertThat(colours).as("distinct colours: text, axes, boxes").hasSizeGreaterThan(50);
        assertThat(drawn).as("pixels unlike the plot's background").isGreaterThan(chart.getWidth()
                * chart.getHeight() / 20);
    }

    @Test
    void theTableOfMeansIsPrintedWithEveryAgent() {
        assertThat(printed).contains("agent          games  fruit mean     sd  min  max  points mean")
                .containsPattern("Roadrunner +3 +\\d+\\.\\d\\d")
                .containsPattern("FirstAgent +3 +\\d+\\.\\d\\d")
                .contains("game 3/3 (seed 42)", "100%", "Missed turns: none");
    }

    @Test
    void anUnknownAgentIsAUsageErrorNamingIt() {
        assertThat(usageError("--agents", "Dwarf,Gandalf"))
                .contains("orchard tournament: invalid value for option '--agents': no agent 'Gandalf'")
                .contains("Roadrunner");
    }

    @Test
    void aGameCountOutOfRangeIsAUsageErrorNamingIt() {
        assertThat(usageError("--games", "0")).contains(
                "orchard tournament: invalid value for option '--games': '0' is out of range (expected 1-1000 games)");
    }

    @Test
    void seedsThatDoNotFitIn64BitsAreAUsageErrorNamingTheFirst() {
        assertThat(usageError("--games", "3", "--seed-from", String.valueOf(Long.MAX_VALUE - 1)))
                .contains("orchard tournament: invalid value for option '--seed-from': '" + (Long.MAX_VALUE - 1)
                        + "' is out of range (expected at most " + (Long.MAX_VALUE - 3));
    }

    /** What {@code ./orchard tournament args} prints on standard error, once it has exited with status 2. */
    private static String usageError(String... args) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        String[] line = Stream.concat(Stream.of("tournament"), Stream.of(args)).toArray(String[]::new);
        PrintStream none = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);

        assertThat(Orchard.run(line, none, new PrintStream(err, true, StandardCharsets.UTF_8))).isEqualTo(2);
        return err.toString(StandardCharsets.UTF_8);
    }
}
