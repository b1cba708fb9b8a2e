package io.orchard.examples;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.DisabledOnOs;
import org.junit.jupiter.api.condition.OS;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code ./orchard} script's build, with a stand-in for Maven that prints what Maven prints and
 * a stand-in for {@code java}: the build shows its progress while it runs, not after.
 */
@DisabledOnOs(OS.WINDOWS)
class OrchardScriptTest {

    /** Maven's stand-in: two modules; between them it waits for the test to say "go", up to 30 s. */
    private static final String MAVEN = """
            #!/bin/sh
            echo '[INFO] Reactor Build Order:'
            echo '[INFO] ----------------------< io.orchard:protocol >-----------------------'
            echo '[INFO] Building Orchard protocol 0.1.0-SNAPSHOT                           [1/2]'
            echo '[INFO]   from protocol/pom.xml'
            waited=0
            while [ ! -f go ] && [ "$waited" -lt 300 ]; do sleep 0.1; waited=$((waited + 1)); done
            echo '[INFO] Building Orchard server 0.1.0-SNAPSHOT                             [2/2]'
            echo '[INFO] Downloading from central: https://repo.maven.apache.org/maven2/io/netty/netty.pom'
            echo '[INFO] Downloaded from central: https://repo.maven.apache.org/maven2/io/netty/netty.pom (2 kB)'
            echo '[INFO] Downloading from central: https://repo.maven.apache.org/maven2/io/netty/netty.jar'
            """;

    @TempDir
    Path dir;

    private final List<String> said = new CopyOnWriteArrayList<>();

    /** A copy of the project's script beside the stand-ins, with Maven "already fetched" unless told otherwise. */
    private Path project(String maven, boolean mavenFetched) throws IOException {
        Path root = dir.resolve("project");
        Files.createDirectories(root.resolve(".mvn/wrapper"));
        Files.copy(Path.of("..", "orchard"), root.resolve("orchard"));
        Files.writeString(root.resolve(".mvn/wrapper/maven-wrapper.properties"), "distributionUrl="
                + "https://repo.maven.apache.org/maven2/org/apache/maven/apache-maven/3.9.11/apache-maven-3.9.11-bin.zip\n");
        executable(root.resolve("mvnw"), maven);
        executable(dir.resolve("jdk/bin/java"), "#!/bin/sh\necho \"java $*\"\n");
        if (mavenFetched) {
            Files.createDirectories(dir.resolve("m2/wrapper/dists/apache-maven-3.9.11/0a1b2c3d"));
        }
        return root;
    }

    private static void executable(Path file, String text) throws IOException {
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
        assertThat(file.toFile().setExecutable(true)).isTrue();
    }

    private Process start(Path root) throws IOException {
        ProcessBuilder builder = new ProcessBuilder("sh", root.resolve("orchard").toString(), "--version")
                .directory(root.toFile());
        builder.environment().put("JAVA_HOME", dir.resolve("jdk").toString());
        builder.environment().put("MAVEN_USER_HOME", dir.resolve("m2").toString());
        Process process = builder.start();
        Thread reader = new Thread(() -> collect(process.getErrorStream()), "orchard-stderr");
        reader.setDaemon(true);
        reader.start();
        return process;
    }

    private void collect(InputStream stream) {
        try (BufferedReader lines = new BufferedReader(new InputStreamReader(stream, StandardCharsets.UTF_8))) {
            String line;
            while ((line = lines.readLine()) != null) {
                said.add(line);
            }
        } catch (IOException e) {
            // the process ended
        }
    }

    private boolean awaitLine(String part) throws InterruptedException {
        for (int i = 0; i < 200; i++) {
            if (said.stream().anyMatch(line -> line.contains(part))) {
                return true;
            }
            Thread.sleep(100);
        }
        return false;
    }

    @Test
    void theFirstBuildNamesEachModuleAsMavenReachesIt() throws Exception {
        Path root = project(MAVEN + "mkdir -p examples/target && : > examples/target/classpath.txt\n", true);
        Process orchard = start(root);
        try {
            assertThat(awaitLine("[1/2] Orchard protocol")).as("the first module while Maven is still on it; said: %s",
                    said).isTrue();
            Files.writeString(root.resolve("go"), "");
            assertThat(orchard.waitFor(60, TimeUnit.SECONDS)).isTrue();
            assertThat(orchard.exitValue()).isZero();
            assertThat(new String(orchard.getInputStream().readAllBytes(), StandardCharsets.UTF_8))
                    .startsWith("java -cp ").endsWith("io.orchard.examples.Orchard --version\n");
            awaitLine("orchard: built in");
            assertThat(said).first().asString().startsWith("orchard: building the project; the first time takes");
            assertThat(said).contains("orchard:   [1/2] Orchard protocol", "orchard:   [2/2] Orchard server",
                    "orchard:         fetching its libraries from Maven Central...")
                    .filteredOn(line -> line.contains("fetching")).hasSize(1);
            assertThat(said).last().asString().matches("orchard: built in \\d+ s");
        } finally {
            orchard.destroyForcibly();
        }
    }

    @Test
    void aFailedBuildShowsMavensErrorsWithoutItsCommentary() throws Exception {
        Path root = project("""
                #!/bin/sh
                echo '[INFO] Building Orchard protocol 0.1.0-SNAPSHOT                           [1/2]'
                echo '[INFO] --- compiler:3.14.0:compile (default-compile) @ protocol ---'
                echo '[ERROR] /project/protocol/src/main/java/Foo.java:[3,1] class, interface, enum, or record expected'
                echo '[INFO] BUILD FAILURE'
                exit 1
                """, true);
        Process orchard = start(root);
        try {
            assertThat(orchard.waitFor(60, TimeUnit.SECONDS)).isTrue();
            assertThat(orchard.exitValue()).isEqualTo(1);
            awaitLine("the build failed");
            assertThat(said).containsSubsequence("orchard:   [1/2] Orchard protocol",
                    "[ERROR] /project/protocol/src/main/java/Foo.java:[3,1] class, interface, enum, or record expected",
                    "orchard: the build failed; its errors are above");
            assertThat(said).noneMatch(line -> line.startsWith("[INFO]"));
            assertThat(root.resolve("examples/target/orchard.stamp")).doesNotExist();
        } finally {
            orchard.destroyForcibly();
        }
    }

    @Test
    void aBuiltProjectIsBuiltAgainForAChangedModuleAndNotForAFolderMavenDoesNotBuild() throws Exception {
        Path root = project("#!/bin/sh\n: > maven-ran\nmkdir -p examples/target && : > examples/target/classpath.txt\n",
                true);
        Files.writeString(root.resolve("pom.xml"), "<project/>");
        for (String module : List.of("protocol", "examples")) {
            Files.createDirectories(root.resolve(module).resolve("src/main"));
            Files.writeString(root.resolve(module).resolve("pom.xml"), "<project/>");
            Files.createDirectories(root.resolve(module).resolve("target/classes"));
        }
        Path python = Files.createDirectories(root.resolve("python/src/orchard_world"));
        Files.writeString(root.resolve("examples/target/classpath.txt"), "");
        Path stamp = Files.writeString(root.resolve("examples/target/orchard.stamp"), "");
        long built = System.currentTimeMillis() - 60_000;
        try (var files = Files.walk(root)) {
            for (Path file : files.toList()) {
                assertThat(file.toFile().setLastModified(built - 60_000)).isTrue();
            }
        }
        assertThat(stamp.toFile().setLastModified(built)).isTrue();
        // pip install ./python writes its egg-info into python/src, after the build
        Files.createDirectories(python.resolveSibling("orchard_world.egg-info"));

        Process orchard = start(root);
        assertThat(orchard.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(orchard.exitValue()).isZero();
        assertThat(root.resolve("maven-ran")).as("built again; said: %s", said).doesNotExist();

        Files.writeString(root.resolve("protocol/src/main/Changed.java"), "class Changed {}");
        Process again = start(root);
        assertThat(again.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(root.resolve("maven-ran")).as("a module's change builds it").exists();
        assertThat(said).contains("orchard: rebuilding the project...");
    }

    @Test
    void fetchingMavenItselfIsSaid() throws Exception {
        Path root = project("#!/bin/sh\nmkdir -p examples/target && : > examples/target/classpath.txt\n", false);
        Process orchard = start(root);
        try {
            assertThat(orchard.waitFor(60, TimeUnit.SECONDS)).isTrue();
            assertThat(orchard.exitValue()).isZero();
            awaitLine("orchard: built in");
            assertThat(said).contains("orchard:   fetching Maven (apache-maven-3.9.11)...");
        } finally {
            orchard.destroyForcibly();
        }
    }
}
