package io.orchard.examples;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The virtual environment the build makes under target/ for the Python package (python/): made once,
 * the package and its dependencies pip-installed into it once a test run, from PyPI.
 */
final class PythonVenv {

    static final Path PACKAGE = Path.of("..", "python").toAbsolutePath().normalize();
    private static final Path VENV = Path.of("target", "python-venv").toAbsolutePath();
    private static Path python;

    /** What a command printed, and how it ended. */
    record Output(int status, String out, String err) {
    }

    private PythonVenv() {
    }

    /** The venv's python, with the package installed (its [test] extra too). */
    static synchronized Path python() throws IOException, InterruptedException {
        if (python == null) {
            assertThat(PACKAGE.resolve("pyproject.toml")).exists();
            Path executable = VENV.resolve("bin").resolve("python");
            if (!Files.isExecutable(executable)) {
                run(List.of(PythonAgentTest.findPython(), "-m", "venv", VENV.toString()), 5);
            }
            run(List.of(executable.toString(), "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
                    PACKAGE + "[test]"), 15);
            python = executable;
        }
        return python;
    }

    /** Runs {@code command} in python/ and checks that it ends well; what it printed, both streams together. */
    static String run(List<String> command, int minutes) throws IOException, InterruptedException {
        Output output = output(command, minutes);
        String both = output.out() + output.err();
        assertThat(output.status()).as("%s:%n%s", command, both).isZero();
        return both;
    }

    /**
     * Runs {@code command} in python/, with the class path of the servers it starts (the test's own),
     * within {@code minutes}.
     */
    static Output output(List<String> command, int minutes) throws IOException, InterruptedException {
        Path out = Files.createTempFile("orchard-python", ".out");
        Path err = Files.createTempFile("orchard-python", ".err");
        try {
            ProcessBuilder builder = new ProcessBuilder(new ArrayList<>(command)).directory(PACKAGE.toFile())
                    .redirectOutput(out.toFile()).redirectError(err.toFile());
            builder.environment().put("ORCHARD_CLASSPATH", System.getProperty("java.class.path"));
            builder.environment().put("PYTHONDONTWRITEBYTECODE", "1");
            Process process = builder.start();
            boolean ended = process.waitFor(minutes, TimeUnit.MINUTES);
            if (!ended) {
                process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
            Output output = new Output(ended ? process.exitValue() : -1, Files.readString(out, StandardCharsets.UTF_8),
                    Files.readString(err, StandardCharsets.UTF_8));
            assertThat(ended).as("%s ended within %d minutes:%n%s%s", command, minutes, output.out(), output.err())
                    .isTrue();
            return output;
        } finally {
            Files.deleteIfExists(out);
            Files.deleteIfExists(err);
        }
    }
}
