package io.orchard.server.world.scenario;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.value.Point2;
import io.orchard.server.world.Bank;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ScenarioFileTest {

    static String example() throws IOException {
        try (InputStream in = ScenarioFileTest.class.getResourceAsStream("/scenarios/example.json")) {
            assertThat(in).as("the example scenario on the test classpath").isNotNull();
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    @Test
    void theExampleScenarioLoadsIntoAWorld() throws IOException {
        World world = World.fromScenario(ScenarioFile.parse(example(), "example.json"));

        assertThat(world.trees()).hasSize(3);
        assertThat(world.tables()).hasSize(1);
        assertThat(world.bridges()).hasSize(2);
        assertThat(world.fruitCount()).isEqualTo(4);
        assertThat(world.bankOf(new Point2(0, -5))).contains(Bank.NORTH);
        assertThat(world.bankOf(new Point2(-15, 25))).contains(Bank.SOUTH);
        assertThat(world.checkMove(new Point2(-10, 0), new Point2(-10, 25), 0.5).isFree()).isTrue();
        assertThat(world.checkMove(new Point2(0, 0), new Point2(0, 25), 0.5).reason())
                .isEqualTo("path enters the river outside a bridge");
    }

    @Test
    void theExampleInTheDocumentationIsTheTestedExample() throws IOException {
        Path docs = findUp(Path.of("docs", "scenarios.md"));
        Matcher block = Pattern.compile("```json\\n(.*?)```", Pattern.DOTALL).matcher(Files.readString(docs));

        assertThat(block.find()).as("a json block in %s", docs).isTrue();
        assertThat(block.group(1)).isEqualTo(example());
    }

    private static Path findUp(Path relative) {
        for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
            if (Files.exists(dir.resolve(relative))) {
                return dir.resolve(relative);
            }
        }
        throw new AssertionError("no " + relative + " above " + Path.of("").toAbsolutePath());
    }

    @Test
    void aGeneratedWorldWrittenOutAndReadBackIsTheSameWorld(@TempDir Path dir) throws IOException {
        World world = WorldGenerator.standard(17).generate();
        Path file = dir.resolve("garden.json");

        ScenarioFile.write(world.toScenario(), file);
        Scenario read = ScenarioFile.read(file);
        World again = World.fromScenario(read);

        assertThat(read).isEqualTo(world.toScenario());
        assertThat(again.toScenario()).isEqualTo(world.toScenario());
        assertThat(ScenarioFile.toJson(again.toScenario())).isEqualTo(Files.readString(file));
    }

    @Test
    void aWorldWithoutItsEatenFruitRoundTripsToo() throws IOException {
        World world = World.fromScenario(ScenarioFile.parse(example(), "example.json"));
        world.removeFruit("F2");

        Scenario read = ScenarioFile.parse(ScenarioFile.toJson(world.toScenario()), "again");

        assertThat(read.fruit()).extracting(f -> f.id()).containsExactly("F1", "F3", "F4");
        assertThat(read.fruit().get(0).support()).isNull();
    }

    @Test
    void writtenFilesLeaveOutAbsentSupportsAndKeepTheFieldOrder() throws IOException {
        String json = ScenarioFile.toJson(ScenarioFile.parse(example(), "example.json"));

        assertThat(json).startsWith("{\n  \"format\": 1,\n  \"bounds\": {");
        assertThat(json).doesNotContain("null");
        assertThat(json.indexOf("\"castle\"")).isLessThan(json.indexOf("\"river\""));
        assertThat(json.indexOf("\"trees\"")).isLessThan(json.indexOf("\"fruit\""));
    }

    @ParameterizedTest(name = "{2}")
    @CsvSource(delimiter = '|', quoteCharacter = '`', textBlock = """
            `"height": 6 }`                          | `"hieght": 6 }`                          | example.json: tree T1: unknown field 'hieght'; known fields: height, id, kind, position, radius (at trees[0].hieght, line 22
            `"format": 1,`                           | `"format": 1, "treez": [],`              | example.json: the scenario: unknown field 'treez'
            `"radius": 0.8, `                        | ``                                       | example.json: table D1: missing field 'radius' (at tables[0]
            `"height": 8`                            | `"hieght": 8`                            | example.json: the castle: unknown field 'hieght'
            `"x": 0, "y": 0.15, "z": -5`             | `"x": NaN, "y": 0.15, "z": -5`           | example.json: fruit F1: x must be a finite number, was NaN (at fruit[0].position
            `"x": 0, "y": 0.15, "z": -5`             | `"x": 1e999, "y": 0.15, "z": -5`         | example.json: fruit F1: x must be a finite number, was Infinity
            `"radius": 0.8`                          | `"radius": -1`                           | example.json: table D1: radius must be greater than 0, was -1.0 (at tables[0]
            `"width": 3 },`                          | `"width": 0 },`                          | example.json: bridge B1: width must be greater than 0, was 0.0
            `"kind": "banana"`                       | `"kind": "pear"`                         | example.json: fruit F2: unknown value 'pear'; expected one of: banana, coconut, tomato (at fruit[1].kind
            `"kind": "tree", "position": { "x": 5`   | `"kind": "bush", "position": { "x": 5`   | example.json: tree T1: unknown value 'bush'; expected one of: table, tree
            `"radius": 0.8`                          | `"radius": "big"`                        | example.json: table D1: expected a number, found the text "big" (at tables[0].radius
            `"id": "T1"`                             | `"id": 7`                                | example.json: tree trees[0]: Cannot coerce Integer value (7) to
            `"format": 1,`                           | `"format": 2,`                           | example.json: the scenario: scenario format 2 is not supported: this server reads format 1
            `"format": 1,`                           | `"format": 1, "format": 1,`              | example.json: the scenario: Duplicate Object property "format"
            `"height": 8`                            | `"height": 8,`                           | example.json: the castle: Unexpected character ('}'
            `"radius": 0.8, "height": 0.9 }`         | `"radius": 0.8, "height": null }`        | example.json: table D1: height must be a number, was null (at tables[0].height
            """)
    void aMalformedFileIsRefusedNamingTheObjectAndWhere(String from, String to, String message) throws IOException {
        String json = example();
        assertThat(json).contains(from);
        String bad = json.replaceFirst(Pattern.quote(from), Matcher.quoteReplacement(to));

        assertThatThrownBy(() -> ScenarioFile.parse(bad, "example.json"))
                .isInstanceOf(ScenarioException.class)
                .hasMessageStartingWith(message);
    }

    @Test
    void aFileThatIsNotAnObjectIsRefused() {
        assertThatThrownBy(() -> ScenarioFile.parse("[]", "list.json"))
                .isInstanceOf(ScenarioException.class)
                .hasMessageStartingWith("list.json: the scenario: ");
    }

    @Test
    void aWellFormedFileWithOverlappingThingsIsRefusedWhenTheWorldIsMade() throws IOException {
        Scenario scenario = ScenarioFile.parse(example().replace("\"x\": 10, \"z\": -15", "\"x\": 5.5, \"z\": -10"), "x");

        assertThatThrownBy(() -> World.fromScenario(scenario))
                .isInstanceOf(ScenarioException.class)
                .hasMessageContaining("tree T1 overlaps tree T2");
    }

    @Test
    void aMissingFileIsAnIoProblemNotAScenarioProblem(@TempDir Path dir) {
        assertThatThrownBy(() -> ScenarioFile.read(dir.resolve("none.json"))).isInstanceOf(IOException.class);
    }
}
