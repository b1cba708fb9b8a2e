package io.orchard.build;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A program outside this repository can depend on Orchard: examples/consumer, a project with a pom
 * of its own and no parent, is built against the published artifacts alone, installed into an
 * empty local repository, offline, and then run. A missing dependency, a class the jars lack or
 * leak, or a resource they do not carry fails it here. Third-party libraries and Maven's plugins
 * come from the user's local repository, read only, behind the temporary one.
 *
 * <p>Runs under Failsafe after the reactor has packaged every module (it needs their jars); the
 * Maven running the build builds the consumer.
 */
class ConsumerProjectIT {

    private static final Duration BUILD_TIMEOUT = Duration.ofMinutes(5);
    private static final Duration GAME_TIMEOUT = Duration.ofMinutes(3);
    private static final String MAIN_CLASS = "org.example.orchardconsumer.ConsumerGame";
    /** Libraries of Orchard's tests that must never reach a program using it. */
    private static final List<String> TEST_LIBRARIES = List.of("/org/junit/", "/org/assertj/", "/net/bytebuddy/",
            "/org/opentest4j/", "/com/code-intelligence/", "/org/openjdk/jmh/");

    @TempDir
    static Path work;

    private static Path repository;
    private static Path consumer;
    private static ProcessResult build;

    @BeforeAll
    static void installTheArtifactsAndBuildTheConsumer() throws IOException, InterruptedException {
        Path root = BuildDriftTest.repositoryRoot();
        MavenBuild maven = MavenBuild.read(root);
        repository = work.resolve("repository");
        long start = System.nanoTime();
        PublishedArtifacts.of(root, maven).forEach(artifact -> artifact.installInto(repository));

        consumer = work.resolve("consumer");
        copyProject(root.resolve("examples/consumer"), consumer);
        String version = maven.builds().get("bom").version();
        build = run(consumer, BUILD_TIMEOUT, maven(), "-B", "-o", "-q", "-f", "pom.xml",
                "-Dmaven.repo.local=" + repository,
                "-Dmaven.repo.local.tail=" + property("orchard.local.repository"),
                "-Dorchard.version=" + version, "package");
        System.out.printf("installed and built the consumer in %d ms%n", (System.nanoTime() - start) / 1_000_000);
    }

    @Test
    void consumerBuildsOfflineAgainstTheInstalledArtifacts() {
        assertThat(build.exitCode()).as("mvn package of examples/consumer, offline:%n%s", build.output()).isZero();
    }

    @Test
    void consumerTakesOrchardFromTheInstalledArtifactsAndNoTestLibrary() throws IOException {
        List<String> classpath = runtimeClasspath();

        assertThat(classpath).filteredOn(entry -> entry.contains("/io/orchard/"))
                .as("Orchard's jars on the consumer's class path")
                .hasSize(4) // server, agents and the protocol and cli they share
                .allMatch(entry -> entry.startsWith(repository.toString()));
        assertThat(classpath).as("the consumer's run-time class path")
                .noneMatch(entry -> TEST_LIBRARIES.stream().anyMatch(entry::contains));
    }

    @Test
    void consumerPlaysALockstepGameAndPrintsTheRanking() throws IOException, InterruptedException {
        Path jar = consumer.resolve("target/orchard-consumer-1.0.0.jar");
        String classpath = jar + java.io.File.pathSeparator + String.join(java.io.File.pathSeparator,
                runtimeClasspath());
        long start = System.nanoTime();

        ProcessResult game = run(consumer, GAME_TIMEOUT, java(), "-cp", classpath, MAIN_CLASS, "1998", "20");

        System.out.printf("the consumer's game took %d ms%n", (System.nanoTime() - start) / 1_000_000);
        assertThat(game.exitCode()).as("the consumer's game:%n%s", game.output()).isZero();
        assertThat(game.output()).as("the consumer's game")
                .containsPattern("world server on port \\d+, seed 1998")
                .contains("Ranking:")
                .containsPattern("(?m)^ +1\\. (Gatherer|Dwarf) +\\d+ points")
                .containsPattern("(?m)^ +2\\. (Gatherer|Dwarf) +\\d+ points");
    }

    private static List<String> runtimeClasspath() throws IOException {
        assertThat(build.exitCode()).as("the consumer's build:%n%s", build.output()).isZero();
        String text = Files.readString(consumer.resolve("target/classpath.txt")).strip();
        return Arrays.asList(text.split(java.io.File.pathSeparator));
    }

    /** Copies the consumer's pom and sources, never a target/ folder left by a build by hand. */
    private static void copyProject(Path from, Path to) throws IOException {
        List<Path> files;
        try (Stream<Path> walk = Files.walk(from)) {
            files = walk.filter(Files::isRegularFile)
                    .filter(file -> !from.relativize(file).startsWith("target"))
                    .toList();
        }
        for (Path file : files) {
            Path target = to.resolve(from.relativize(file).toString());
            Files.createDirectories(target.getParent());
            Files.copy(file, target);
        }
    }

    private static String maven() {
        return Path.of(property("orchard.maven.home"), "bin", "mvn").toString();
    }

    private static String java() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }

    private static String property(String name) {
        String value = System.getProperty(name);
        assertThat(value).as("system property %s, which examples/pom.xml gives Failsafe", name).isNotBlank();
        return value;
    }

    record ProcessResult(int exitCode, String output) {
    }

    /** Runs a command in {@code dir} with this JVM's Java, its output and errors together. */
    private static ProcessResult run(Path dir, Duration timeout, String... command)
            throws IOException, InterruptedException {
        ProcessBuilder builder = new ProcessBuilder(new ArrayList<>(List.of(command))).directory(dir.toFile())
                .redirectErrorStream(true);
        Map<String, String> environment = builder.environment();
        environment.put("JAVA_HOME", System.getProperty("java.home"));
        environment.remove("MAVEN_ARGS");
        Path log = Files.createTempFile(work, "output", ".txt");
        builder.redirectOutput(log.toFile());
        Process process = builder.start();
        if (!process.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
            process.destroyForcibly().waitFor();
            return new ProcessResult(-1, "timed out after " + timeout + ": " + String.join(" ", command) + "\n"
                    + Files.readString(log, StandardCharsets.UTF_8));
        }
        return new ProcessResult(process.exitValue(), Files.readString(log, StandardCharsets.UTF_8));
    }
}
