package io.orchard.build;

import io.orchard.build.ModuleBuild.Usage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The Gradle build as its Kotlin scripts declare it: the modules settings.gradle.kts includes, the
 * version catalog, and each module's coordinates and dependencies from its build.gradle.kts. The
 * scripts are read with a few regular expressions, not run, so they must keep to the plain forms
 * used here; a dependency line in any other form is rejected with the line, rather than skipped.
 *
 * @param modules the modules settings.gradle.kts includes, in order
 * @param catalog gradle/libs.versions.toml
 * @param builds  each module's build, by module name
 */
record GradleBuild(List<String> modules, VersionCatalog catalog, Map<String, ModuleBuild> builds) {

    private static final Pattern BLOCK_COMMENT = Pattern.compile("(?s)/\\*.*?\\*/");
    private static final Pattern LINE_COMMENT = Pattern.compile("(?m)^\\s*//.*$");
    private static final Pattern INCLUDE = Pattern.compile("\\binclude\\s*\\((?<arguments>[^)]*)\\)");
    private static final Pattern STRING = Pattern.compile("\"(?<text>[^\"]*)\"");
    private static final Pattern GROUP = Pattern.compile("(?m)^group\\s*=\\s*\"(?<value>[^\"]*)\"");
    private static final Pattern VERSION = Pattern.compile("(?m)^version\\s*=\\s*\"(?<value>[^\"]*)\"");
    private static final Pattern DEPENDENCIES = Pattern.compile("(?m)^dependencies\\s*\\{");
    private static final Pattern DECLARATION = Pattern.compile("(?<configuration>\\w+)\\s*\\((?<notation>.*)\\)");
    private static final Pattern PROJECT = Pattern.compile("project\\(\\s*\"(?<path>[^\"]+)\"\\s*\\)");
    private static final Pattern PLATFORM = Pattern.compile("(?:platform|enforcedPlatform)\\(.*\\)");
    private static final Pattern CATALOG_ENTRY = Pattern.compile("libs(?:\\.\\w+)+");
    private static final Pattern COORDINATES =
            Pattern.compile("\"(?<group>[^\":]+):(?<artifact>[^\":]+)(?::[^\"]*)?\"");

    GradleBuild {
        modules = List.copyOf(modules);
        builds = Map.copyOf(builds);
    }

    /** Reads settings.gradle.kts and gradle/libs.versions.toml in {@code root}, and each included module's script. */
    static GradleBuild read(Path root) throws IOException {
        List<String> modules = includedModules(Files.readString(root.resolve("settings.gradle.kts")));
        VersionCatalog catalog = VersionCatalog.parse(Files.readString(root.resolve("gradle/libs.versions.toml")));
        Map<String, ModuleBuild> builds = new LinkedHashMap<>();
        for (String module : modules) {
            Path script = root.resolve(module).resolve("build.gradle.kts");
            builds.put(module, moduleBuild(module, withoutComments(Files.readString(script)), catalog, script));
        }
        return new GradleBuild(modules, catalog, builds);
    }

    private static List<String> includedModules(String settings) {
        List<String> modules = new ArrayList<>();
        Matcher include = INCLUDE.matcher(withoutComments(settings));
        while (include.find()) {
            Matcher name = STRING.matcher(include.group("arguments"));
            while (name.find()) {
                modules.add(name.group("text").replaceFirst("^:", ""));
            }
        }
        return modules;
    }

    private static ModuleBuild moduleBuild(String module, String script, VersionCatalog catalog, Path file) {
        Map<String, Usage> onModules = new HashMap<>();
        Map<String, Usage> onLibraries = new HashMap<>();
        for (String line : dependencyLines(script)) {
            Matcher declaration = DECLARATION.matcher(line);
            if (!declaration.matches()) {
                throw new IllegalArgumentException(
                        "expected configuration(notation) in the dependencies of " + file + ", was: " + line);
            }
            Usage usage = declaration.group("configuration").startsWith("test") ? Usage.TEST : Usage.MAIN;
            String notation = declaration.group("notation").strip();
            Matcher project = PROJECT.matcher(notation);
            Matcher coordinates = COORDINATES.matcher(notation);
            if (project.matches()) {
                onModules.merge(project.group("path").replaceFirst("^:", ""), usage, Usage::wider);
            } else if (PLATFORM.matcher(notation).matches()) {
                continue; // a BOM manages versions, as <dependencyManagement> does in a pom
            } else if (CATALOG_ENTRY.matcher(notation).matches()) {
                VersionCatalog.Library library = catalog.byAccessor(notation).orElseThrow(
                        () -> new IllegalArgumentException(file + " names " + notation
                                + ", expected one of the version catalog's libraries"));
                onLibraries.merge(library.module(), usage, Usage::wider);
            } else if (coordinates.matches()) {
                onLibraries.merge(coordinates.group("group") + ":" + coordinates.group("artifact"),
                        usage, Usage::wider);
            } else {
                throw new IllegalArgumentException("expected project(\":module\"), platform(...), libs.<alias> or "
                        + "\"group:artifact:version\" in the dependencies of " + file + ", was: " + line);
            }
        }
        return new ModuleBuild(module, value(GROUP, script), value(VERSION, script), onModules, onLibraries);
    }

    /**
     * The lines of the script's top-level {@code dependencies { }} block, without blank lines and
     * trailing comments; none if it has no such block.
     */
    private static List<String> dependencyLines(String script) {
        Matcher start = DEPENDENCIES.matcher(script);
        if (!start.find()) {
            return List.of();
        }
        int depth = 1;
        int end = start.end();
        while (depth > 0) {
            if (end == script.length()) {
                throw new IllegalArgumentException("expected a closing } for the dependencies block, was: "
                        + script.substring(start.start()));
            }
            char c = script.charAt(end++);
            depth += c == '{' ? 1 : c == '}' ? -1 : 0;
        }
        return script.substring(start.end(), end - 1).lines()
                .map(line -> line.replaceFirst("\\s*//.*$", "").strip())
                .filter(line -> !line.isEmpty())
                .toList();
    }

    private static String value(Pattern assignment, String script) {
        Matcher matcher = assignment.matcher(script);
        return matcher.find() ? matcher.group("value") : null;
    }

    private static String withoutComments(String script) {
        return LINE_COMMENT.matcher(BLOCK_COMMENT.matcher(script).replaceAll("")).replaceAll("");
    }
}
