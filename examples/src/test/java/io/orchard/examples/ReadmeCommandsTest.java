package io.orchard.examples;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * CI runs the README's two commands as written: .ci/run calls the test command exactly, and the
 * demo command with only flags added after it (a bounded game, headless).
 */
class ReadmeCommandsTest {

    private static final Path ROOT = Path.of("..");
    private static final Pattern CODE_BLOCK = Pattern.compile("```\\n(.*?)```", Pattern.DOTALL);

    @Test
    void theReadmesFirstCommandIsTheDemoAndItsTestCommandIsTheMavenBuild() throws IOException {
        List<String> commands = readmeCommands();

        assertThat(commands).as("the README's commands, in order").isNotEmpty();
        assertThat(commands.get(0)).isEqualTo("./orchard demo");
        assertThat(commands).contains("./mvnw -B verify");
    }

    @Test
    void ciRunsTheReadmesTestCommandExactly() throws IOException {
        List<String> ci = ciLines();

        assertThat(ci).as(".ci/run").contains("./mvnw -B verify");
    }

    @Test
    void ciRunsTheReadmesDemoCommandWithABoundedGameHeadless() throws IOException {
        String demo = readmeCommands().get(0);

        assertThat(ciLines()).as(".ci/run").anySatisfy(line -> assertThat(line).startsWith(demo + " ")
                .contains(" --headless").containsPattern(" --time-limit \\d+"));
    }

    @Test
    void theReadmesSetUpInstallsEveryPackageCiInstallsOnABareMachine() throws IOException {
        Matcher need = Pattern.compile("need\\+=\\(([^)]*)\\)").matcher(Files.readString(ROOT.resolve(".ci/run"),
                StandardCharsets.UTF_8));
        List<String> packages = new ArrayList<>();
        while (need.find()) {
            packages.addAll(List.of(need.group(1).strip().split("\\s+")));
        }
        String readme = Files.readString(ROOT.resolve("README.md"), StandardCharsets.UTF_8);
        Matcher block = CODE_BLOCK.matcher(readme);
        List<String> installed = new ArrayList<>();
        while (block.find()) {
            for (String command : block.group(1).replace("\\\n", " ").lines().toList()) {
                if (command.strip().startsWith("apt-get install ")) {
                    installed.addAll(List.of(command.strip().split("\\s+")));
                }
            }
        }

        assertThat(packages).as("the packages .ci/run installs").contains("xvfb", "libgl1-mesa-dri", "python3");
        assertThat(installed).as("the README's apt-get install").containsAll(packages);
    }

    /** The lines of the README's code blocks that run a program of the repository, in order. */
    private static List<String> readmeCommands() throws IOException {
        String readme = Files.readString(ROOT.resolve("README.md"), StandardCharsets.UTF_8);
        Matcher block = CODE_BLOCK.matcher(readme);
        List<String> commands = new ArrayList<>();
        while (block.find()) {
            block.group(1).lines().map(String::strip).filter(line -> line.startsWith("./")).forEach(commands::add);
        }
        return commands;
    }

    /** The lines of .ci/run, stripped, without blank lines and comments. */
    private static List<String> ciLines() throws IOException {
        return Files.readAllLines(ROOT.resolve(".ci/run"), StandardCharsets.UTF_8).stream().map(String::strip)
                .filter(line -> !line.isEmpty() && !line.startsWith("#")).toList();
    }
}
