package io.orchard.build;

import static java.util.Map.entry;

import io.orchard.build.ModuleBuild.Usage;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
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
            entry("slf4j", "slf4j.version"),
            entry("logback", "logback.version"),
            entry("junit", "junit.version"),
            entry("assertj", "assertj.version"),
            entry("jsonschema-generator", "jsonschema-generator.version"),
            entry("jmh", "jmh.version"),
            entry("jazzer", "jazzer.version"),
            entry("xchart", "xchart.version"),
            entry("picocli", "picocli.version"));

    /** Root pom properties ending in this hold library versions. */
    private static final String VERSION_SUFFIX = ".version";
    private static final String PRESENT = "present";

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

    /** Each module must depend on the same other modules, for main code or tests, in both builds. */
    static List<Drift> moduleDependencies(MavenBuild maven, GradleBuild gradle) {
        return dependencies(maven, gradle, ModuleBuild::modules, "on module ");
    }

    /** Each module must depend on the same libraries ({@code group:artifact}), for main code or tests, in both. */
    static List<Drift> libraryDependencies(MavenBuild maven, GradleBuild gradle) {
        return dependencies(maven, gradle, ModuleBuild::libraries, "on library ");
    }

    /** Each module must have the same group and version in both builds. */
    static List<Drift> coordinates(MavenBuild maven, GradleBuild gradle) {
        List<Drift> drifts = new ArrayList<>();
        for (String module : sharedModules(maven, gradle)) {
            ModuleBuild pom = maven.builds().get(module);
            ModuleBuild script = gradle.builds().get(module);
            if (!Objects.equals(pom.group(), script.group())) {
                drifts.add(new Drift(module + " group", orAbsent(pom.group()), orAbsent(script.group())));
            }
            if (!Objects.equals(pom.version(), script.version())) {
                drifts.add(new Drift(module + " version", orAbsent(pom.version()), orAbsent(script.version())));
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
