package io.orchard.examples;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * The Python package {@code orchard-world} (python/) passes its own tests: the client against real
 * servers, PettingZoo's and Gymnasium's checks of its environments, a game of a Python agent. They
 * run with pytest in a virtual environment the build makes under target/, into which pip installs
 * the package and its dependencies from PyPI; the servers they start run on this test's class path.
 */
class PythonPackageTest {

    private static final Path PACKAGE = Path.of("..", "python").toAbsolutePath().normalize();
    private static final Path VENV = Path.of("target", "python-venv").toAbsolutePath();

    @Test
    void thePythonPackagesTestsPassAgainstRealServers() throws Exception {
        assertThat(PACKAGE.resolve("pyproject.toml")).exists();
        Path python = VENV.resolve("bin").resolve("python");
        if (!Files.isExecutable(python)) {
            run(List.of(PythonAgentTest.findPython(), "-m", "venv", VENV.toString()), 5);
        }
        run(List.of(python.toString(), "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
                PACKAGE + "[test]"), 15);
        String output = run(List.of(python.toString(), "-m", "pytest", "-q", "-p", "no:cacheprovider",
                PACKAGE.resolve("tests").toString()), 30);
        Matcher passed = Pattern.compile("(\\d+) passed").matcher(output);
        assertThat(passed.find()).as(output).isTrue();
        assertThat(Integer.parseInt(passed.group(1))).as(output).isGreaterThanOrEqualTo(30);
        assertThat(Pattern.compile("\\d+ (failed|skipped|errors?)\\b").matcher(output).find()).as(output).isFalse();
    }

    /** Runs {@code command} in python/, with the class path of the servers it starts; its output. */
    private static String run(List<String> command, int minutes) throws IOException, InterruptedException {
        Path log = Files.createTempFile("orchard-python", ".log");
        try {
            ProcessBuilder builder = new ProcessBuilder(new ArrayList<>(command)).directory(PACKAGE.toFile())
                    .redirectErrorStream(true).redirectOutput(log.toFile());
            builder.environment().put("ORCHARD_CLASSPATH", System.getProperty("java.class.path"));
            builder.environment().put("PYTHONDONTWRITEBYTECODE", "1");
            Process process = builder.start();
            boolean ended = process.waitFor(minutes, TimeUnit.MINUTES);
            if (!ended) {
                process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
            String output = Files.readString(log, StandardCharsets.UTF_8);
            assertThat(ended).as("%s ended within %d minutes:%n%s", command, minutes, output).isTrue();
            assertThat(process.exitValue()).as("%s:%n%s", command, output).isZero();
            return output;
        } finally {
            Files.deleteIfExists(log);
        }
    }
}
