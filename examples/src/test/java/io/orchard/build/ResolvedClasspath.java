package io.orchard.build;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The library versions a build resolved, read from the jars on a classpath. Understands the layout
 * of a Maven repository ({@code .../org/slf4j/slf4j-api/2.0.20/slf4j-api-2.0.20.jar}) and of
 * Gradle's cache ({@code .../org.slf4j/slf4j-api/2.0.20/<sha1>/slf4j-api-2.0.20.jar}).
 */
final class ResolvedClasspath {

    private static final Pattern GRADLE_CACHE = Pattern.compile(
            "/files-2\\.1/(?<group>[^/]+)/(?<artifact>[^/]+)/(?<version>[^/]+)/[0-9a-f]+/[^/]+\\.jar$");

    private final List<String> entries;

    private ResolvedClasspath(List<String> entries) {
        this.entries = entries;
    }

    /** The classpath this JVM was started with: under Surefire or Gradle, the test runtime classpath. */
    static ResolvedClasspath current() {
        return of(System.getProperty("java.class.path", ""));
    }

    /** A classpath in the form of {@code java.class.path}: entries separated by {@link File#pathSeparator}. */
    static ResolvedClasspath of(String classpath) {
        return new ResolvedClasspath(Arrays.stream(classpath.split(Pattern.quote(File.pathSeparator)))
                .map(entry -> entry.replace('\\', '/'))
                .toList());
    }

    /** A library's jar on the classpath. */
    record Jar(String group, String artifact, String version) {

        @Override
        public String toString() {
            return group + ":" + artifact + ":" + version;
        }
    }

    /**
     * The libraries' jars on the classpath: those in Gradle's cache, and those in the Maven
     * repository {@code localRepository} if it is given (the group of a jar there is its folder's
     * path). Anything else, such as a module's own classes, is left out.
     */
    List<Jar> jars(Optional<Path> localRepository) {
        List<Jar> jars = new ArrayList<>();
        String repository = localRepository.map(path -> path.toAbsolutePath().normalize().toString()
                .replace('\\', '/') + "/").orElse(null);
        for (String entry : entries) {
            Matcher cached = GRADLE_CACHE.matcher(entry);
            if (cached.find()) {
                jars.add(new Jar(cached.group("group"), cached.group("artifact"), cached.group("version")));
            } else if (repository != null && entry.startsWith(repository) && entry.endsWith(".jar")) {
                String[] folders = entry.substring(repository.length()).split("/");
                if (folders.length >= 4) {
                    int n = folders.length;
                    jars.add(new Jar(String.join(".", Arrays.asList(folders).subList(0, n - 3)), folders[n - 3],
                            folders[n - 2]));
                }
            }
        }
        return jars;
    }

    /** The version of {@code group:artifact} whose jar is on the classpath, if it is there. */
    Optional<String> versionOf(String group, String artifact) {
        String a = Pattern.quote(artifact);
        Pattern jar = Pattern.compile("/(?:" + Pattern.quote(group.replace('.', '/')) + "|" + Pattern.quote(group)
                + ")/" + a + "/(?<version>[^/]+)/(?:[0-9a-f]+/)?" + a + "-\\k<version>(?:-[^/]+)?\\.jar$");
        return entries.stream()
                .map(jar::matcher)
                .filter(Matcher::find)
                .map(matcher -> matcher.group("version"))
                .findFirst();
    }
}
