package io.orchard.build;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.build.ResolvedClasspath.Jar;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;

/**
 * A library released as a family of modules (Jackson, Netty, LWJGL, jMonkeyEngine, JUnit...) must
 * be on the class path in one version: a module of the family in another version, such as a
 * jackson-core that a transitive dependency brings in an older version than jackson-databind's,
 * runs code its siblings were never built against. The examples module's test class path holds
 * every library of the project, under Maven as under Gradle.
 */
class DependencyFamiliesTest {

    /** Groups whose modules are released together under several group ids, by the family's name. */
    private static final Map<String, String> FAMILIES_BY_GROUP_PREFIX = Map.of(
            "tools.jackson", "Jackson 3",
            "io.netty", "Netty");

    /**
     * Groups that hold separate libraries, each released on its own and versioned alone: each of
     * their artifacts is a family of its own (Typesafe's Config and ssl-config, which Pekko brings).
     */
    private static final Set<String> GROUPS_OF_SEPARATE_LIBRARIES = Set.of("com.typesafe");

    /** The families the class path surely holds, so the check is known to see them. */
    private static final List<String> SURELY_PRESENT = List.of("Jackson 3", "Netty", "org.lwjgl",
            "org.jmonkeyengine", "org.slf4j", "org.junit.jupiter");

    @Test
    void everyFamilyOnTheTestClasspathIsInOneVersion() {
        Map<String, Set<String>> versions = versionsByFamily(testClasspathJars());

        assertThat(versions).as("families on the test class path").containsKeys(SURELY_PRESENT.toArray(String[]::new));
        assertThat(versions).as("families with more than one version on the test class path: %s", versions)
                .allSatisfy((family, found) -> assertThat(found).as(family).hasSize(1));
    }

    @Test
    void separateLibrariesOfOneGroupAreFamiliesOfTheirOwn() {
        List<Jar> jars = List.of(new Jar("com.typesafe", "config", "1.4.9"),
                new Jar("com.typesafe", "ssl-config-core_2.13", "0.7.1"));

        assertThat(versionsByFamily(jars)).containsEntry("com.typesafe:config", Set.of("1.4.9"))
                .containsEntry("com.typesafe:ssl-config-core_2.13", Set.of("0.7.1"));
    }

    @Test
    void aFamilyInTwoVersionsIsReported() {
        List<Jar> jars = List.of(new Jar("tools.jackson.core", "jackson-databind", "3.2.4"),
                new Jar("tools.jackson.core", "jackson-core", "3.0.3"),
                new Jar("io.netty", "netty-handler", "4.2.20.Final"));

        assertThat(versionsByFamily(jars)).containsEntry("Jackson 3", Set.of("3.0.3", "3.2.4"))
                .containsEntry("Netty", Set.of("4.2.20.Final"));
    }

    /** The libraries on this JVM's class path: Surefire passes Maven's local repository to read them. */
    static List<Jar> testClasspathJars() {
        Optional<Path> repository = Optional.ofNullable(System.getProperty("orchard.local.repository")).map(Path::of);
        return ResolvedClasspath.of(System.getProperty("java.class.path", "")).jars(repository);
    }

    /**
     * The versions of each family among {@code jars}: a family is a group, or groups sharing a prefix,
     * or an artifact of a group of separate libraries.
     */
    static Map<String, Set<String>> versionsByFamily(List<Jar> jars) {
        Map<String, Set<String>> versions = new TreeMap<>();
        for (Jar jar : jars) {
            String family = FAMILIES_BY_GROUP_PREFIX.entrySet().stream()
                    .filter(prefix -> jar.group().equals(prefix.getKey()) || jar.group().startsWith(prefix.getKey() + "."))
                    .map(Map.Entry::getValue)
                    .findFirst()
                    .orElse(GROUPS_OF_SEPARATE_LIBRARIES.contains(jar.group()) ? jar.group() + ":" + jar.artifact()
                            : jar.group());
            versions.computeIfAbsent(family, f -> new TreeSet<>()).add(jar.version());
        }
        return versions;
    }
}
