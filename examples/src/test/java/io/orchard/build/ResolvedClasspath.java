package io.orchard.build;

import java.io.File;
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
