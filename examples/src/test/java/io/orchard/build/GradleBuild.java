package io.orchard.build;

import io.orchard.build.ModuleBuild.Kind;
import io.orchard.build.ModuleBuild.Usage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The Gradle build as its Kotlin scripts declare it: the modules settings.gradle.kts includes, the
 * version catalog, what the convention scripts under gradle/ set, and each module's coordinates,
 * plugins, dependencies and settings from its build.gradle.kts. The scripts are read with a few
 * regular expressions, not run, so they must keep to the plain forms used here; a dependency line
 * in any other form is rejected with the line, rather than skipped.
 *
 * @param modules  the modules settings.gradle.kts includes, in order
 * @param catalog  gradle/libs.versions.toml
 * @param settings what the convention scripts set for every module, by the names
 *                 {@link MavenBuild#settings()} uses
 * @param builds   each module's build, by module name
 */
record GradleBuild(List<String> modules, VersionCatalog catalog, Map<String, String> settings,
        Map<String, ModuleBuild> builds) {

    /** The script every module applies: compiler, tests and the BOM imports. */
    static final String JAVA_CONVENTIONS = "gradle/java-conventions.gradle.kts";
    /** The script every published module applies: its jars and its POM. */
    static final String PUBLISH_CONVENTIONS = "gradle/publish-conventions.gradle.kts";
    /** The working directory every run task must have: the one gradle was started from. */
    static final String CALLERS_DIRECTORY = "gradle.startParameter.currentDir";

    private static final Pattern BLOCK_COMMENT = Pattern.compile("(?s)/\\*.*?\\*/");
    private static final Pattern LINE_COMMENT = Pattern.compile("(?m)^\\s*//.*$");
    private static final Pattern INCLUDE = Pattern.compile("\\binclude\\s*\\((?<arguments>[^)]*)\\)");
    private static final Pattern STRING = Pattern.compile("\"(?<text>[^\"]*)\"");
    private static final Pattern GROUP = Pattern.compile("(?m)^group\\s*=\\s*\"(?<value>[^\"]*)\"");
    private static final Pattern VERSION = Pattern.compile("(?m)^version\\s*=\\s*\"(?<value>[^\"]*)\"");
    private static final Pattern ARTIFACT = Pattern.compile("(?m)^\\s*artifactId\\s*=\\s*\"(?<value>[^\"]*)\"");
    private static final Pattern DESCRIPTION = Pattern.compile("(?m)^description\\s*=\\s*\"(?<value>[^\"]*)\"");
    private static final Pattern MAIN_CLASS = Pattern.compile("(?m)^\\s*mainClass\\s*=\\s*\"(?<value>[^\"]*)\"");
    private static final Pattern WORKING_DIR = Pattern.compile("(?m)^\\s*workingDir\\s*=\\s*(?<value>\\S+)\\s*$");
    private static final Pattern CLASSPATH_ADD = Pattern.compile("(?m)^\\s*classpath\\s*\\+=\\s*(?<value>\\w+)\\s*$");
    private static final Pattern CREATED_CONFIGURATION =
            Pattern.compile("(?m)^val\\s+(?<name>\\w+)\\s+by\\s+configurations\\.creating\\s*$");
    private static final Pattern PLUGINS = Pattern.compile("(?m)^plugins\\s*\\{");
    private static final Pattern PLUGIN = Pattern.compile("`?(?<id>[\\w-]+)`?");
    private static final Pattern APPLIED_SCRIPT =
            Pattern.compile("apply\\(from\\s*=\\s*rootProject\\.file\\(\"(?<path>[^\"]+)\"\\)\\)");
    private static final Pattern DEPENDENCIES = Pattern.compile("(?m)^dependencies\\s*\\{");
    private static final Pattern CONSTRAINTS = Pattern.compile("(?m)^\\s*constraints\\s*\\{");
    private static final Pattern DECLARATION = Pattern.compile("(?<configuration>\\w+)\\s*\\((?<notation>.*)\\)");
    /** A declaration with a block after it: {@code implementation(libs.x) { exclude(...) }}, folded onto one line. */
    private static final Pattern WITH_BLOCK = Pattern.compile("(?<declaration>.*\\))\\s*\\{(?<block>.*)}");
    private static final Pattern EXCLUDE = Pattern.compile(
            "exclude\\(\\s*group\\s*=\\s*\"(?<group>[^\"]+)\"\\s*,\\s*module\\s*=\\s*\"(?<module>[^\"]+)\"\\s*\\)");
    private static final Pattern PROJECT = Pattern.compile("project\\(\\s*\"(?<path>[^\"]+)\"\\s*\\)");
    private static final Pattern PLATFORM = Pattern.compile("(?:platform|enforcedPlatform)\\(.*\\)");
    private static final Pattern CATALOG_ENTRY = Pattern.compile("libs(?:\\.\\w+)+");
    private static final Pattern COORDINATES =
            Pattern.compile("\"(?<group>[^\":]+):(?<artifact>[^\":]+)(?::[^\"]*)?\"");
    private static final Pattern BOMS = Pattern.compile("(?m)^val\\s+boms\\s*=\\s*listOf\\((?<aliases>[^)]*)\\)");
    private static final Pattern RELEASE = Pattern.compile("options\\.release\\.set\\((?<value>\\d+)\\)");
    private static final Pattern ENCODING = Pattern.compile("options\\.encoding\\s*=\\s*\"(?<value>[^\"]*)\"");
    private static final Pattern COMPILER_ARGS =
            Pattern.compile("options\\.compilerArgs\\.addAll\\(listOf\\((?<value>[^)]*)\\)\\)");
    private static final Pattern MAX_HEAP = Pattern.compile("maxHeapSize\\s*=\\s*\"(?<value>[^\"]*)\"");
    private static final Pattern DOCLINT = Pattern.compile("addStringOption\\(\"Xdoclint:(?<value>[^\"]*)\",\\s*\"-quiet\"\\)");
    private static final Pattern WERROR = Pattern.compile("addBooleanOption\\(\"Werror\",\\s*(?<value>true|false)\\)");
    private static final Pattern MODULE_NAME =
            Pattern.compile("attributes\\(\"Automatic-Module-Name\"\\s+to\\s+\"(?<value>[^\"]*)\"\\)");
    private static final Pattern SET = Pattern.compile("(?<field>\\w+)\\.set\\(\"(?<value>[^\"]*)\"\\)");

    GradleBuild {
        modules = List.copyOf(modules);
        settings = Map.copyOf(settings);
        builds = Map.copyOf(builds);
    }

    /**
     * Reads settings.gradle.kts, gradle/libs.versions.toml and the convention scripts in {@code root},
     * and each included module's script.
     */
    static GradleBuild read(Path root) throws IOException {
        List<String> modules = includedModules(Files.readString(root.resolve("settings.gradle.kts")));
        VersionCatalog catalog = VersionCatalog.parse(Files.readString(root.resolve("gradle/libs.versions.toml")));
        String java = withoutComments(Files.readString(root.resolve(JAVA_CONVENTIONS)));
        String publish = withoutComments(Files.readString(root.resolve(PUBLISH_CONVENTIONS)));
        Map<String, ModuleBuild> builds = new LinkedHashMap<>();
        for (String module : modules) {
            Path script = root.resolve(module).resolve("build.gradle.kts");
            builds.put(module, moduleBuild(module, withoutComments(Files.readString(script)), catalog, publish,
                    script));
        }
        return new GradleBuild(modules, catalog, settings(java, publish, catalog), builds);
    }

    private static Map<String, String> settings(String java, String publish, VersionCatalog catalog) {
        Map<String, String> settings = new LinkedHashMap<>();
        Matcher boms = BOMS.matcher(java);
        if (boms.find()) {
            List<String> modules = new ArrayList<>();
            Matcher alias = STRING.matcher(boms.group("aliases"));
            while (alias.find()) {
                String name = alias.group("text");
                modules.add(catalog.libraries().containsKey(name) ? catalog.libraries().get(name).module()
                        : "no catalog library " + name);
            }
            settings.put("BOM imports", String.join(", ", modules.stream().sorted().toList()));
        }
        find(ENCODING, java).ifPresent(encoding -> settings.put("source encoding", encoding));
        find(RELEASE, java).ifPresent(release -> settings.put("compiler release", release));
        find(COMPILER_ARGS, java).ifPresent(arguments -> settings.put("compiler arguments",
                String.join(" ", strings(arguments))));
        find(MAX_HEAP, java).ifPresent(heap -> settings.put("test JVM arguments", "-Xmx" + heap));
        find(DOCLINT, publish).ifPresent(doclint -> settings.put("Javadoc doclint", doclint));
        find(WERROR, publish).ifPresent(werror -> settings.put("Javadoc fails on warnings", werror));
        return settings;
    }

    private static List<String> includedModules(String settings) {
        List<String> modules = new ArrayList<>();
        Matcher include = INCLUDE.matcher(withoutComments(settings));
        while (include.find()) {
            modules.addAll(strings(include.group("arguments")).stream().map(name -> name.replaceFirst("^:", ""))
                    .toList());
        }
        return modules;
    }

    private static ModuleBuild moduleBuild(String module, String script, VersionCatalog catalog, String publish,
            Path file) {
        Set<String> plugins = plugins(script);
        Set<String> scripts = new HashSet<>();
        Matcher applied = APPLIED_SCRIPT.matcher(script);
        while (applied.find()) {
            scripts.add(applied.group("path"));
        }
        Set<String> createdConfigurations = new HashSet<>();
        Matcher created = CREATED_CONFIGURATION.matcher(script);
        while (created.find()) {
            createdConfigurations.add(created.group("name"));
        }

        Map<String, Usage> onModules = new HashMap<>();
        Map<String, Usage> onLibraries = new HashMap<>();
        Map<String, List<String>> ownConfigurations = new TreeMap<>();
        List<String> constrained = new ArrayList<>();
        Map<String, String> exclusions = new TreeMap<>();
        List<String> lines = dependencyLines(script);
        for (String marked : lines) {
            boolean constraint = marked.startsWith(CONSTRAINT);
            String line = constraint ? marked.substring(CONSTRAINT.length()) : marked;
            List<String> excluded = new ArrayList<>();
            Matcher withBlock = WITH_BLOCK.matcher(line);
            if (withBlock.matches()) {
                String block = withBlock.group("block");
                Matcher exclude = EXCLUDE.matcher(block);
                while (exclude.find()) {
                    excluded.add(exclude.group("group") + ":" + exclude.group("module"));
                }
                if (!EXCLUDE.matcher(block).replaceAll("").replace(";", "").isBlank()) {
                    throw new IllegalArgumentException("expected only exclude(group = \"...\", module = \"...\") in "
                            + "the block of a dependency in " + file + ", was: " + line);
                }
                line = withBlock.group("declaration");
            }
            Matcher declaration = DECLARATION.matcher(line);
            if (!declaration.matches()) {
                throw new IllegalArgumentException(
                        "expected configuration(notation) in the dependencies of " + file + ", was: " + line);
            }
            String configuration = declaration.group("configuration");
            String notation = declaration.group("notation").strip();
            Matcher project = PROJECT.matcher(notation);
            Matcher coordinates = COORDINATES.matcher(notation);
            String dependency;
            boolean isModule = false;
            if (project.matches()) {
                dependency = project.group("path").replaceFirst("^:", "");
                isModule = true;
            } else if (PLATFORM.matcher(notation).matches()) {
                continue; // a BOM manages versions, as <dependencyManagement> does in a pom
            } else if (CATALOG_ENTRY.matcher(notation).matches()) {
                dependency = catalog.byAccessor(notation).orElseThrow(
                        () -> new IllegalArgumentException(file + " names " + notation
                                + ", expected one of the version catalog's libraries")).module();
            } else if (coordinates.matches()) {
                dependency = coordinates.group("group") + ":" + coordinates.group("artifact");
            } else {
                throw new IllegalArgumentException("expected project(\":module\"), platform(...), libs.<alias> or "
                        + "\"group:artifact:version\" in the dependencies of " + file + ", was: " + line);
            }
            if (!excluded.isEmpty()) {
                exclusions.put("exclusions of " + dependency, String.join(", ", excluded.stream().sorted().toList()));
            }
            if (constraint) {
                constrained.add(dependency);
            } else if (createdConfigurations.contains(configuration)) {
                ownConfigurations.computeIfAbsent(configuration, name -> new ArrayList<>()).add(dependency);
            } else {
                Usage usage = usage(configuration, file, line);
                (isModule ? onModules : onLibraries).merge(dependency, usage, Usage::wider);
            }
        }

        Kind kind = plugins.contains("java-platform") ? Kind.PLATFORM
                : plugins.contains("java-library") && plugins.contains("maven-publish") ? Kind.LIBRARY
                : Kind.PROGRAM;
        Map<String, String> settings = new LinkedHashMap<>();
        if (kind != Kind.PROGRAM && scripts.contains(PUBLISH_CONVENTIONS)) {
            settings.put("pom name", kind == Kind.PLATFORM ? "Orchard BOM" : "Orchard " + module);
            find(DESCRIPTION, script).ifPresent(description -> settings.put("pom description", description));
            Map<String, String> pom = pomFields(publish);
            pom.forEach(settings::put);
            if (kind == Kind.LIBRARY) {
                find(MODULE_NAME, publish).ifPresent(name -> settings.put("Automatic-Module-Name",
                        name.replace("${project.name}", module)));
                if (publish.contains("withSourcesJar()")) {
                    settings.put("sources jar", "yes");
                }
                if (publish.contains("withJavadocJar()")) {
                    settings.put("Javadoc jar", "yes");
                }
            }
        }
        if (kind == Kind.PLATFORM) {
            settings.put("managed modules", String.join(", ", constrained.stream().sorted().toList()));
        }
        if (plugins.contains("application")) {
            find(MAIN_CLASS, script).ifPresent(main -> settings.put("main class", main));
            settings.put("run working directory", find(WORKING_DIR, script).orElse("the module's directory"));
            List<String> runOnly = new ArrayList<>();
            Matcher added = CLASSPATH_ADD.matcher(script);
            while (added.find()) {
                runOnly.addAll(ownConfigurations.getOrDefault(added.group("value"), List.of()));
            }
            settings.put("run-only libraries", String.join(", ", runOnly.stream().sorted().toList()));
        }
        settings.putAll(exclusions);
        return new ModuleBuild(module, find(GROUP, script).orElse(null), find(ARTIFACT, script).orElse(module),
                find(VERSION, script).orElse(null), kind, onModules, onLibraries, settings);
    }

    /** The Maven scope that Gradle's maven-publish gives a configuration's dependencies. */
    private static Usage usage(String configuration, Path file, String line) {
        if (configuration.startsWith("test")) {
            return Usage.TEST;
        }
        return switch (configuration) {
            case "api", "implementation" -> Usage.COMPILE;
            case "runtimeOnly" -> Usage.RUNTIME;
            case "compileOnly", "compileOnlyApi" -> Usage.PROVIDED;
            default -> throw new IllegalArgumentException("expected api, implementation, runtimeOnly, compileOnly, "
                    + "a test configuration or one the script creates, in the dependencies of " + file + ", was: "
                    + line);
        };
    }

    /** The plugin ids of the script's {@code plugins { }} block. */
    private static Set<String> plugins(String script) {
        Set<String> plugins = new HashSet<>();
        Matcher start = PLUGINS.matcher(script);
        if (start.find()) {
            for (String line : block(script, start.end()).lines().map(String::strip).filter(l -> !l.isEmpty())
                    .toList()) {
                Matcher plugin = PLUGIN.matcher(line);
                if (!plugin.matches()) {
                    throw new IllegalArgumentException("expected a plugin id, alone on its line, in the plugins "
                            + "block, was: " + line);
                }
                plugins.add(plugin.group("id"));
            }
        }
        return plugins;
    }

    /** The POM fields the publish conventions set, by the names MavenBuild uses. */
    private static Map<String, String> pomFields(String publish) {
        Map<String, String> fields = new LinkedHashMap<>();
        Matcher pom = Pattern.compile("(?m)^\\s*pom\\s*\\{").matcher(publish);
        if (!pom.find()) {
            return fields;
        }
        String body = block(publish, pom.end());
        Map<String, String> licence = sets(named(body, "license"));
        Map<String, String> developer = sets(named(body, "developer"));
        Map<String, String> scm = sets(named(body, "scm"));
        String top = body.replace(named(body, "licenses"), "").replace(named(body, "developers"), "")
                .replace(named(body, "scm"), "");
        Optional.ofNullable(sets(top).get("url")).ifPresent(url -> fields.put("pom url", url));
        fields.put("pom licence", licence.getOrDefault("name", "") + " " + licence.getOrDefault("url", ""));
        fields.put("pom developer", developer.getOrDefault("id", "") + " " + developer.getOrDefault("name", ""));
        fields.put("pom scm", scm.getOrDefault("connection", "") + " " + scm.getOrDefault("developerConnection", "")
                + " " + scm.getOrDefault("url", ""));
        return fields;
    }

    /** The {@code field.set("value")} calls directly in {@code text}, by field. */
    private static Map<String, String> sets(String text) {
        Map<String, String> values = new HashMap<>();
        Matcher set = SET.matcher(text);
        while (set.find()) {
            values.putIfAbsent(set.group("field"), set.group("value"));
        }
        return values;
    }

    /** The text of the first {@code name { }} block in {@code text}, or empty. */
    private static String named(String text, String name) {
        Matcher start = Pattern.compile("\\b" + name + "\\s*\\{").matcher(text);
        return start.find() ? text.substring(start.start(), start.end()) + block(text, start.end()) + "}" : "";
    }

    /** The text from {@code from}, just after a '{', to its matching '}'. */
    private static String block(String script, int from) {
        int depth = 1;
        int end = from;
        while (depth > 0) {
            if (end == script.length()) {
                throw new IllegalArgumentException("expected a closing } for the block of: "
                        + script.substring(Math.max(0, from - 40), from));
            }
            char c = script.charAt(end++);
            depth += c == '{' ? 1 : c == '}' ? -1 : 0;
        }
        return script.substring(from, end - 1);
    }

    private static List<String> strings(String text) {
        List<String> strings = new ArrayList<>();
        Matcher string = STRING.matcher(text);
        while (string.find()) {
            strings.add(string.group("text"));
        }
        return strings;
    }

    private static Optional<String> find(Pattern pattern, String text) {
        Matcher matcher = pattern.matcher(text);
        return matcher.find() ? Optional.of(matcher.group("value")) : Optional.empty();
    }

    /** Marks a line of a {@code constraints { }} block among the dependency lines. */
    private static final String CONSTRAINT = "constraint:";

    /**
     * The lines of the script's top-level {@code dependencies { }} block, without blank lines and
     * trailing comments, those of a {@code constraints { }} block in it marked as such; none if it
     * has no such block.
     */
    private static List<String> dependencyLines(String script) {
        Matcher start = DEPENDENCIES.matcher(script);
        if (!start.find()) {
            return List.of();
        }
        String body = block(script, start.end());
        List<String> lines = new ArrayList<>();
        Matcher constraints = CONSTRAINTS.matcher(body);
        if (constraints.find()) {
            String inside = block(body, constraints.end());
            inside.lines().map(GradleBuild::declarationLine).filter(line -> !line.isEmpty())
                    .forEach(line -> lines.add(CONSTRAINT + line));
            body = body.substring(0, constraints.start()) + body.substring(constraints.end() + inside.length() + 1);
        }
        StringBuilder open = null;
        for (String line : body.lines().map(GradleBuild::declarationLine).filter(line -> !line.isEmpty()).toList()) {
            if (open != null) {
                open.append(line.equals("}") ? "}" : line + ";");
                if (line.equals("}")) {
                    lines.add(open.toString());
                    open = null;
                }
            } else if (line.endsWith("{")) {
                open = new StringBuilder(line);
            } else {
                lines.add(line);
            }
        }
        return lines;
    }

    private static String declarationLine(String line) {
        return line.replaceFirst("\\s*//.*$", "").strip();
    }

    private static String withoutComments(String script) {
        return LINE_COMMENT.matcher(BLOCK_COMMENT.matcher(script).replaceAll("")).replaceAll("");
    }
}
