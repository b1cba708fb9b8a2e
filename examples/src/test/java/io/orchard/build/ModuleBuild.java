package io.orchard.build;

import java.util.Map;

/**
 * What one module's build file (pom.xml or build.gradle.kts) declares, in terms both builds share.
 *
 * @param name      the module's directory, which is also its Gradle project name
 * @param group     the group the module is published under, or {@code null} if the file sets none
 * @param version   the module's version, or {@code null} if the file sets none
 * @param modules   dependencies on other modules of this repository, by module name
 * @param libraries dependencies on external libraries, by {@code group:artifact}
 */
record ModuleBuild(String name, String group, String version, Map<String, Usage> modules,
        Map<String, Usage> libraries) {

    ModuleBuild {
        modules = Map.copyOf(modules);
        libraries = Map.copyOf(libraries);
    }

    /** Which classpaths a dependency is on, whatever each build calls it (scope or configuration). */
    enum Usage {
        /** Main code and tests: Maven's compile, runtime and provided scopes; Gradle's api, implementation... */
        MAIN,
        /** Tests only: Maven's test scope; Gradle's testImplementation, testRuntimeOnly... */
        TEST;

        /** The usage of a dependency declared twice in one file: main code wins, as tests see it too. */
        static Usage wider(Usage a, Usage b) {
            return a == MAIN || b == MAIN ? MAIN : TEST;
        }

        @Override
        public String toString() {
            return this == MAIN ? "main" : "test";
        }
    }
}
