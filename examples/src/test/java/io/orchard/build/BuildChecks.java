package io.orchard.build;

import static java.util.Map.entry;

import io.orchard.build.ModuleBuild.Kind;
import io.orchard.build.ModuleBuild.Usage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.Function;

/**
 * The comparisons between the Maven and the Gradle build. Each returns the drifts it finds, sorted
 * by item, and an empty list when the builds agree.
 */
final class BuildChecks {

    /**
     * The root pom property that holds the version of each {@code [versions]} entry of
     * gradle/libs.versions.toml. A library version added to either build goes here too.
     */
    static final Map<String, String> VERSION_PROPERTIES = Map.ofEntries(
            entry("jackson", "jackson.version"),
            entry("netty", "netty.version"),
            entry("jts", "jts.version"),
            entry("jme", "jme.version"),
            entry("lwjgl", "lwjgl.version"),
            entry("slf4j", "slf4j.version"),
            entry("logback", "logback.version"),
            entry("junit", "junit.version"),
            entry("assertj", "assertj.version"),
            entry("jsonschema-generator", "jsonschema-generator.version"),
            entry("jmh", "jmh.version"),
            entry("jazzer", "jazzer.version"),
            entry("xchart", "xchart.version"),
            entry("picocli", "picocli.version"),
            entry("archunit", "archunit.version"),
            entry("json-schema-validator", "json-schema-validator.version"),
            entry("pekko", "pekko.version"),
            entry("scala", "scala.version"),
            entry("typesafe-config", "typesafe-config.version"));

    /** Root pom properties ending in this hold library versions. */
    private static final String VERSION_SUFFIX = ".version";
    private static final String PRESENT = "present";
    private static final String MAIN_CLASS = "main class";
    private static final String RUN_WORKING_DIRECTORY = "run working directory";
    private static final String RUN_ONLY_LIBRARIES = "run-only libraries";
    private static final Set<String> GRADLE_RUN_SETTINGS = Set.of(RUN_WORKING_DIRECTORY, RUN_ONLY_LIBRARIES);
    private static final String SLF4J_API = "org.slf4j:slf4j-api";
    private static final String SLF4J_PROVIDER = "ch.qos.logback:logback-classic";

    private BuildChecks() {
    }

    /** The modules settings.gradle.kts includes must be the root pom's {@code <modules>}, in any order. */
    static List<Drift> modules(MavenBuild maven, GradleBuild gradle) {
        List<Drift> drifts = new ArrayList<>();
        for (String module : union(maven.modules(), gradle.modules())) {
            String inMaven = maven.modules().contains(module) ? PRESENT : Drift.ABSENT;
            String inGradle = gradle.modules().contains(module) ? PRESENT : Drift.ABSENT;
            if (!inMaven.equals(inGradle)) {
                drifts.add(new Drift("module " + module, inMaven, inGradle));
            }
        }
        return drifts;
    }

    /** Every catalog version must equal its root pom property, and every library version property must have one. */
    static List<Drift> versions(MavenBuild maven, VersionCatalog catalog) {
        List<Drift> drifts = new ArrayList<>();
        for (String key : new TreeSet<>(catalog.versions().keySet())) {
            String property = VERSION_PROPERTIES.get(key);
            String version = catalog.versions().get(key);
            if (property == null) {
                drifts.add(new Drift("version " + key, "no property mapped to it in BuildChecks.VERSION_PROPERTIES",
                        version));
            } else if (!version.equals(maven.properties().get(property))) {
                drifts.add(new Drift("version " + key + " (property " + property + ")",
                        orAbsent(maven.properties().get(property)), version));
            }
        }
        for (String property : new TreeSet<>(maven.properties().keySet())) {
            String key = VERSION_PROPERTIES.entrySet().stream()
                    .filter(mapping -> mapping.getValue().equals(property))
                    .map(Map.Entry::getKey)
                    .findFirst()
                    .orElse(null);
            String version = maven.properties().get(property);
            if (key == null && property.endsWith(VERSION_SUFFIX)) {
                drifts.add(new Drift("property " + property, version,
                        "no catalog version mapped to it in BuildChecks.VERSION_PROPERTIES"));
            } else if (key != null && !catalog.versions().containsKey(key)) {
                drifts.add(new Drift("version " + key + " (property " + property + ")", version, Drift.ABSENT));
            }
        }
        return drifts;
    }

    /**
     * Every catalog library whose jar is on {@code classpath} must be there in its catalog version:
     * under Maven, every catalog version is the one Maven resolves.
     */
    static List<Drift> resolvedVersions(VersionCatalog catalog, ResolvedClasspath classpath) {
        List<Drift> drifts = new ArrayList<>();
        for (String alias : new TreeSet<>(catalog.libraries().keySet())) {
            VersionCatalog.Library library = catalog.libraries().get(alias);
            if (library.version() == null) {
                continue; // its version comes from a platform, whose own version is checked
            }
            classpath.versionOf(library.group(), library.artifact())
                    .filter(resolved -> !resolved.equals(library.version()))
                    .ifPresent(resolved -> drifts.add(new Drift(
                            "resolved version of library " + alias + " (" + library.module() + ")",
                            resolved, library.version())));
        }
        return drifts;
    }

    /** Each module must depend on the same other modules, in the same Maven scope, in both builds. */
    static List<Drift> moduleDependencies(MavenBuild maven, GradleBuild gradle) {
        return dependencies(maven, gradle, ModuleBuild::modules, "on module ");
    }

    /**
     * Each module must depend on the same libraries ({@code group:artifact}) in both, in the same
     * Maven scope: Gradle's api and implementation are compile, runtimeOnly is runtime.
     */
    static List<Drift> libraryDependencies(MavenBuild maven, GradleBuild gradle) {
        return dependencies(maven, gradle, ModuleBuild::libraries, "on library ");
    }

    /** Each module must have the same group, artifact and version in both builds. */
    static List<Drift> coordinates(MavenBuild maven, GradleBuild gradle) {
        List<Drift> drifts = new ArrayList<>();
        for (String module : sharedModules(maven, gradle)) {
            ModuleBuild pom = maven.builds().get(module);
            ModuleBuild script = gradle.builds().get(module);
            if (!Objects.equals(pom.group(), script.group())) {
                drifts.add(new Drift(module + " group", orAbsent(pom.group()), orAbsent(script.group())));
            }
            if (!Objects.equals(pom.artifact(), script.artifact())) {
                drifts.add(new Drift(module + " artifact", orAbsent(pom.artifact()), orAbsent(script.artifact())));
            }
            if (!Objects.equals(pom.version(), script.version())) {
                drifts.add(new Drift(module + " version", orAbsent(pom.version()), orAbsent(script.version())));
            }
        }
        return drifts;
    }

    /** Each module must build the same kind of thing (library, BOM, programs) in both builds. */
    static List<Drift> kinds(MavenBuild maven, GradleBuild gradle) {
        List<Drift> drifts = new ArrayList<>();
        for (String module : sharedModules(maven, gradle)) {
            Kind inMaven = maven.builds().get(module).kind();
            Kind inGradle = gradle.builds().get(module).kind();
            if (inMaven != inGradle) {
                drifts.add(new Drift(module + " kind", inMaven.toString(), inGradle.toString()));
            }
        }
        return drifts;
    }

    /**
     * What the root pom sets for every module (BOM imports, compiler, test JVM, Javadoc) must be
     * what the convention scripts under gradle/ set.
     */
    static List<Drift> settings(MavenBuild maven, GradleBuild gradle) {
        return compare("", maven.settings(), gradle.settings(), key -> false);
    }

    /**
     * What each module's build sets beyond its dependencies (POM metadata, Automatic-Module-Name,
     * sources and Javadoc jars, the BOM's modules, the main class) must be the same in both builds.
     * Only Gradle has run tasks for the server and the viewer: their settings are {@link #runTasks}'.
     */
    static List<Drift> moduleSettings(MavenBuild maven, GradleBuild gradle) {
        List<Drift> drifts = new ArrayList<>();
        for (String module : sharedModules(maven, gradle)) {
            Map<String, String> inMaven = maven.builds().get(module).settings();
            drifts.addAll(compare(module + " ", inMaven, gradle.builds().get(module).settings(),
                    key -> GRADLE_RUN_SETTINGS.contains(key) || key.equals(MAIN_CLASS) && !inMaven.containsKey(key)));
        }
        return drifts;
    }

    /**
     * Each Gradle run task must run an existing main class of its module, in the directory gradle was
     * started from (as ./orchard and the Maven run profile do, not in the module's folder), with an
     * SLF4J provider on its class path when the module logs through SLF4J. Reported against what
     * is expected, in the place of Maven's side.
     */
    static List<Drift> runTasks(GradleBuild gradle, Path root) {
        List<Drift> drifts = new ArrayList<>();
        for (ModuleBuild build : new TreeMap<>(gradle.builds()).values()) {
            Map<String, String> settings = build.settings();
            if (!settings.containsKey(RUN_WORKING_DIRECTORY)) {
                continue;
            }
            String main = settings.get(MAIN_CLASS);
            Path source = main == null ? null : root.resolve(build.name()).resolve("src/main/java")
                    .resolve(main.replace('.', '/') + ".java");
            if (source == null || !Files.isRegularFile(source)) {
                drifts.add(new Drift(build.name() + " run main class", "a class of src/main/java", orAbsent(main)));
            }
            if (!GradleBuild.CALLERS_DIRECTORY.equals(settings.get(RUN_WORKING_DIRECTORY))) {
                drifts.add(new Drift(build.name() + " run working directory", GradleBuild.CALLERS_DIRECTORY,
                        settings.get(RUN_WORKING_DIRECTORY)));
            }
            boolean logs = build.libraries().get(SLF4J_API) == Usage.COMPILE;
            Usage provider = build.libraries().get(SLF4J_PROVIDER);
            boolean provided = provider == Usage.COMPILE || provider == Usage.RUNTIME
                    || settings.getOrDefault(RUN_ONLY_LIBRARIES, "").contains(SLF4J_PROVIDER);
            if (logs && !provided) {
                drifts.add(new Drift(build.name() + " run SLF4J provider", SLF4J_PROVIDER, Drift.ABSENT));
            }
        }
        return drifts;
    }

    private static List<Drift> compare(String prefix, Map<String, String> inMaven, Map<String, String> inGradle,
            java.util.function.Predicate<String> gradleOnly) {
        List<Drift> drifts = new ArrayList<>();
        for (String key : union(inMaven.keySet(), inGradle.keySet())) {
            if (gradleOnly.test(key)) {
                continue;
            }
            String mavenValue = inMaven.get(key);
            String gradleValue = inGradle.get(key);
            if (!Objects.equals(mavenValue, gradleValue)) {
                drifts.add(new Drift(prefix + key, orAbsent(mavenValue), orAbsent(gradleValue)));
            }
        }
        return drifts;
    }

    private static List<Drift> dependencies(MavenBuild maven, GradleBuild gradle,
            Function<ModuleBuild, Map<String, Usage>> kind, String label) {
        List<Drift> drifts = new ArrayList<>();
        for (String module : sharedModules(maven, gradle)) {
            Map<String, Usage> inMaven = kind.apply(maven.builds().get(module));
            Map<String, Usage> inGradle = kind.apply(gradle.builds().get(module));
            for (String dependency : union(inMaven.keySet(), inGradle.keySet())) {
                Usage mavenUsage = inMaven.get(dependency);
                Usage gradleUsage = inGradle.get(dependency);
                if (mavenUsage != gradleUsage) {
                    drifts.add(new Drift(module + " dependency " + label + dependency,
                            usage(mavenUsage), usage(gradleUsage)));
                }
            }
        }
        return drifts;
    }

    /** The modules of both builds; a module only one build has is reported by {@link #modules}. */
    private static Set<String> sharedModules(MavenBuild maven, GradleBuild gradle) {
        Set<String> shared = new TreeSet<>(maven.builds().keySet());
        shared.retainAll(gradle.builds().keySet());
        return shared;
    }

    private static Set<String> union(Collection<String> a, Collection<String> b) {
        Set<String> union = new TreeSet<>(a);
        union.addAll(b);
        return union;
    }

    private static String usage(Usage usage) {
        return usage == null ? Drift.ABSENT : usage.toString();
    }

    private static String orAbsent(String value) {
        return value == null ? Drift.ABSENT : value;
    }
}
