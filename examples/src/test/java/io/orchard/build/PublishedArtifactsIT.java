package io.orchard.build;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.build.ModuleBuild.Kind;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.jar.JarFile;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.api.Test;

/**
 * What each published library's jars hold, read as {@code jar tf} would: the main jar has every
 * class and resource of the module and no test class, and a stable module name; the sources jar
 * has every source file; the Javadoc jar has a page for every public type. And the launcher's
 * class path (./orchard) holds run-time libraries only.
 */
class PublishedArtifactsIT {

    private static final Pattern PUBLIC_TYPE = Pattern.compile(
            "(?m)^public\\s+(?:(?:final|abstract|sealed|non-sealed|static)\\s+)*(?:class|interface|record|enum|@interface)\\s+(?<name>\\w+)");

    static List<String> libraries() throws IOException {
        return MavenBuild.read(BuildDriftTest.repositoryRoot()).builds().values().stream()
                .filter(build -> build.kind() == Kind.LIBRARY)
                .map(ModuleBuild::name)
                .sorted()
                .toList();
    }

    @ParameterizedTest
    @MethodSource("libraries")
    void mainJarHoldsTheModulesClassesAndResourcesAndNoTestClass(String module) throws IOException {
        Path dir = BuildDriftTest.repositoryRoot().resolve(module);
        Set<String> entries = entries(jar(dir, ""));

        assertThat(entries).as("%s's jar", module)
                .containsAll(files(dir.resolve("target/classes"), ".class"))
                .containsAll(files(dir.resolve("src/main/resources"), ""))
                .doesNotContainAnyElementsOf(files(dir.resolve("target/test-classes"), ".class"));
        try (JarFile jar = new JarFile(jar(dir, "").toFile())) {
            assertThat(jar.getManifest().getMainAttributes().getValue("Automatic-Module-Name"))
                    .as("Automatic-Module-Name of %s's jar", module)
                    .isEqualTo("io.orchard." + module);
        }
    }

    @ParameterizedTest
    @MethodSource("libraries")
    void sourcesJarHoldsEverySourceFile(String module) throws IOException {
        Path dir = BuildDriftTest.repositoryRoot().resolve(module);

        assertThat(entries(jar(dir, "-sources"))).as("%s's sources jar", module)
                .containsAll(files(dir.resolve("src/main/java"), ".java"));
    }

    @ParameterizedTest
    @MethodSource("libraries")
    void javadocJarHasAPageForEveryPublicType(String module) throws IOException {
        Path dir = BuildDriftTest.repositoryRoot().resolve(module);
        Path sources = dir.resolve("src/main/java");
        Set<String> pages;
        try (Stream<Path> walk = Files.walk(sources)) {
            pages = walk.filter(file -> file.toString().endsWith(".java")).filter(file -> {
                try {
                    return PUBLIC_TYPE.matcher(Files.readString(file)).find();
                } catch (IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }).map(file -> sources.relativize(file).toString().replace(File.separatorChar, '/')
                    .replaceFirst("\\.java$", ".html")).collect(Collectors.toSet());
        }

        assertThat(pages).as("public types of %s", module).isNotEmpty();
        assertThat(entries(jar(dir, "-javadoc"))).as("%s's Javadoc jar", module)
                .contains("index.html")
                .containsAll(pages);
    }

    @Test
    void launcherClasspathHoldsRuntimeLibrariesOnly() throws IOException {
        Path file = BuildDriftTest.repositoryRoot().resolve("examples/target/classpath.txt");
        List<String> classpath = List.of(Files.readString(file).strip().split(File.pathSeparator));

        assertThat(classpath).as("the launcher's class path, %s", file)
                .anyMatch(entry -> entry.contains("logback-classic"))
                .noneMatch(entry -> Stream.of("/org/junit/", "/org/assertj/", "/net/bytebuddy/", "/org/opentest4j/")
                        .anyMatch(entry::contains));
    }

    private static Path jar(Path module, String suffix) {
        String name = module.getFileName().toString();
        try {
            String version = MavenBuild.read(BuildDriftTest.repositoryRoot()).builds().get(name).version();
            Path jar = module.resolve("target").resolve(name + "-" + version + suffix + ".jar");
            assertThat(jar).as("run with ./mvnw verify, which packages it first").isRegularFile();
            return jar;
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static Set<String> entries(Path jar) throws IOException {
        try (JarFile file = new JarFile(jar.toFile())) {
            return file.stream().map(entry -> entry.getName()).collect(Collectors.toSet());
        }
    }

    /** The files under {@code dir} whose names end in {@code suffix}, by their path relative to it with '/'. */
    private static Set<String> files(Path dir, String suffix) throws IOException {
        if (!Files.isDirectory(dir)) {
            return Set.of();
        }
        try (Stream<Path> walk = Files.walk(dir)) {
            return walk.filter(Files::isRegularFile)
                    .filter(file -> file.toString().endsWith(suffix))
                    .map(file -> dir.relativize(file).toString().replace(File.separatorChar, '/'))
                    .collect(Collectors.toSet());
        }
    }
}
