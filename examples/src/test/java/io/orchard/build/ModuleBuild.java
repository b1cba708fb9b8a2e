package io.orchard.build;

import java.util.Map;

/**
 * What one module's build file (pom.xml or build.gradle.kts) declares, in terms both builds share.
 *
 * @param name      the module's directory, which is also its Gradle project name
 * @param group     the group the module is published under, or {@code null} if the file sets none
 * @param artifact  the artifact the module is published as
 * @param version   the module's version, or {@code null} if the file sets none
 * @param kind      what the module builds
 * @param modules   dependencies on other modules of this repository, by module name
 * @param libraries dependencies on external libraries, by {@code group:artifact}
 * @param settings  what the module's build sets beyond its dependencies, by a name both builds
 *                  share ({@code "Automatic-Module-Name"}, {@code "pom licence"}...); a setting
 *                  the file lacks is absent
 */
record ModuleBuild(String name, String group, String artifact, String version, Kind kind, Map<String, Usage> modules,
        Map<String, Usage> libraries, Map<String, String> settings) {

    ModuleBuild {
        modules = Map.copyOf(modules);
        libraries = Map.copyOf(libraries);
        settings = Map.copyOf(settings);
    }

    /** What a module builds, whatever each build calls it (packaging, plugins). */
    enum Kind {
        /** A published jar: Maven's jar packaging, deployed; Gradle's java-library with maven-publish. */
        LIBRARY,
        /** A published BOM: Maven's pom packaging; Gradle's java-platform with maven-publish. */
        PLATFORM,
        /** Programs, never published: Maven's jar packaging with maven.deploy.skip; Gradle without maven-publish. */
        PROGRAM;

        @Override
        public String toString() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /**
     * Which class paths a dependency is on, whatever each build calls it: Maven's scope, or the
     * Gradle configurations that Gradle's maven-publish maps to that scope.
     */
    enum Usage {
        /** Compiling and running the module and its users: Maven's compile scope; Gradle's api and implementation. */
        COMPILE,
        /** Running the module and its users, never compiling it: Maven's runtime scope; Gradle's runtimeOnly. */
        RUNTIME,
        /** Compiling the module only: Maven's provided scope; Gradle's compileOnly and compileOnlyApi. */
        PROVIDED,
        /** The tests only: Maven's test scope; Gradle's testImplementation, testRuntimeOnly... */
        TEST;

        /** The usage of a dependency declared twice in one file: the one on more class paths wins. */
        static Usage wider(Usage a, Usage b) {
            return a.ordinal() <= b.ordinal() ? a : b;
        }

        @Override
        public String toString() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }
}
