package io.orchard.build;

import io.orchard.build.ModuleBuild.Kind;
import io.orchard.build.ModuleBuild.Usage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.xml.sax.SAXException;

/**
 * The Maven build as its poms declare it: the root pom's modules, properties and build-wide
 * settings, and for each module its coordinates, kind, dependencies (including those every module
 * inherits from the root) and settings.
 *
 * @param modules    the root pom's {@code <modules>}, in order
 * @param properties the root pom's {@code <properties>}
 * @param settings   what the root pom sets for every module (compiler, test JVM, BOM imports,
 *                   Javadoc), by the names {@link GradleBuild#settings()} uses
 * @param builds     each module's build, by module name
 */
record MavenBuild(List<String> modules, Map<String, String> properties, Map<String, String> settings,
        Map<String, ModuleBuild> builds) {

    private static final Pattern PLACEHOLDER = Pattern.compile("\\$\\{([^}]+)}");
    private static final String RUN_PROFILE = "run";
    private static final Pattern EXEC_MAIN_CLASS = Pattern.compile("%classpath\\s+(?<main>[\\w.$]+)");

    MavenBuild {
        modules = List.copyOf(modules);
        properties = Map.copyOf(properties);
        settings = Map.copyOf(settings);
        builds = Map.copyOf(builds);
    }

    /** Reads the root pom.xml in {@code root} and the pom.xml of each module it lists. */
    static MavenBuild read(Path root) throws IOException {
        Element parent = parse(root.resolve("pom.xml"));
        List<String> modules = children(child(parent, "modules"), "module").stream()
                .map(MavenBuild::text)
                .toList();
        Map<String, String> properties = new LinkedHashMap<>();
        for (Element property : children(child(parent, "properties"), null)) {
            properties.put(property.getLocalName(), text(property));
        }
        String groupId = childText(parent, "groupId").orElseThrow(
                () -> new IllegalArgumentException("root pom.xml has no <groupId>: " + root));
        String version = childText(parent, "version").orElseThrow(
                () -> new IllegalArgumentException("root pom.xml has no <version>: " + root));

        Map<String, Element> poms = new LinkedHashMap<>();
        Map<String, String> moduleByArtifact = new HashMap<>();
        for (String module : modules) {
            Element pom = parse(root.resolve(module).resolve("pom.xml"));
            poms.put(module, pom);
            childText(pom, "artifactId").ifPresent(artifact -> moduleByArtifact.put(artifact, module));
        }

        Map<String, ModuleBuild> builds = new LinkedHashMap<>();
        for (var entry : poms.entrySet()) {
            Element pom = entry.getValue();
            boolean inherits = child(pom, "parent") != null;
            Map<String, String> values = new HashMap<>(inherits ? properties : Map.of());
            for (Element property : children(child(pom, "properties"), null)) {
                values.put(property.getLocalName(), text(property));
            }
            values.put("project.groupId", childText(pom, "groupId").orElse(groupId));
            values.put("project.version", childText(pom, "version").orElse(version));
            values.put("project.artifactId", childText(pom, "artifactId").orElse(entry.getKey()));

            // A module inherits the root's <dependencies>; its own declaration of one replaces it.
            Map<String, Usage> declared = inherits ? dependencies(parent, values) : new LinkedHashMap<>();
            declared.putAll(dependencies(pom, values));
            Map<String, Usage> onModules = new HashMap<>();
            Map<String, Usage> onLibraries = new HashMap<>();
            declared.forEach((coordinates, usage) -> {
                String[] parts = coordinates.split(":", 2);
                String module = moduleByArtifact.get(parts[1]);
                if (parts[0].equals(groupId) && module != null) {
                    onModules.put(module, usage);
                } else {
                    onLibraries.put(coordinates, usage);
                }
            });
            Kind kind = "pom".equals(childText(pom, "packaging").orElse("jar")) ? Kind.PLATFORM
                    : "true".equals(values.get("maven.deploy.skip")) ? Kind.PROGRAM : Kind.LIBRARY;
            Map<String, String> moduleSettings = moduleSettings(kind, inherits ? parent : pom, pom, values,
                    moduleByArtifact);
            builds.put(entry.getKey(), new ModuleBuild(entry.getKey(), values.get("project.groupId"),
                    values.get("project.artifactId"), values.get("project.version"), kind, onModules, onLibraries, moduleSettings));
        }
        return new MavenBuild(modules, properties, settings(parent, properties), builds);
    }

    /** What the root pom sets for every module, by the names GradleBuild uses. */
    private static Map<String, String> settings(Element root, Map<String, String> properties) {
        Map<String, String> settings = new LinkedHashMap<>();
        List<String> boms = new ArrayList<>();
        for (Element dependency : children(child(child(root, "dependencyManagement"), "dependencies"), "dependency")) {
            if ("import".equals(childText(dependency, "scope").orElse(""))) {
                boms.add(childText(dependency, "groupId").orElse("") + ":"
                        + childText(dependency, "artifactId").orElse(""));
            }
        }
        settings.put("BOM imports", String.join(", ", boms.stream().sorted().toList()));
        settings.put("source encoding", properties.get("project.build.sourceEncoding"));
        Element compiler = pluginConfiguration(root, "maven-compiler-plugin");
        childText(compiler, "release").ifPresent(release -> settings.put("compiler release", resolve(release,
                properties)));
        settings.put("compiler arguments", String.join(" ", children(child(compiler, "compilerArgs"), "arg").stream()
                .map(MavenBuild::text).toList()));
        childText(pluginConfiguration(root, "maven-surefire-plugin"), "argLine")
                .ifPresent(argLine -> settings.put("test JVM arguments", resolve(argLine, properties)));
        Element javadoc = pluginConfiguration(root, "maven-javadoc-plugin");
        childText(javadoc, "doclint").ifPresent(doclint -> settings.put("Javadoc doclint", doclint));
        childText(javadoc, "failOnWarnings").ifPresent(fail -> settings.put("Javadoc fails on warnings", fail));
        return settings;
    }

    /**
     * What a module's build sets beyond its dependencies: for a published module its POM metadata
     * (from {@code metadata}, the root pom or its own), for a library its jars' settings, for a
     * program with a run profile the main class its exec plugin runs.
     */
    private static Map<String, String> moduleSettings(Kind kind, Element metadata, Element pom,
            Map<String, String> values, Map<String, String> moduleByArtifact) {
        Map<String, String> settings = new LinkedHashMap<>();
        if (kind != Kind.PROGRAM) {
            childText(pom, "name").ifPresent(name -> settings.put("pom name", name));
            childText(pom, "description").ifPresent(description -> settings.put("pom description", description));
            childText(metadata, "url").ifPresent(url -> settings.put("pom url", url));
            Element licence = child(child(metadata, "licenses"), "license");
            settings.put("pom licence", childText(licence, "name").orElse("") + " "
                    + childText(licence, "url").orElse(""));
            Element developer = child(child(metadata, "developers"), "developer");
            settings.put("pom developer", childText(developer, "id").orElse("") + " "
                    + childText(developer, "name").orElse(""));
            Element scm = child(metadata, "scm");
            settings.put("pom scm", childText(scm, "connection").orElse("") + " "
                    + childText(scm, "developerConnection").orElse("") + " " + childText(scm, "url").orElse(""));
        }
        if (kind == Kind.LIBRARY) {
            Element jar = pluginConfiguration(metadata, "maven-jar-plugin");
            childText(child(child(jar, "archive"), "manifestEntries"), "Automatic-Module-Name")
                    .ifPresent(name -> settings.put("Automatic-Module-Name", resolve(name, values)));
            if (hasPlugin(metadata, "maven-source-plugin") && !"true".equals(values.get("maven.source.skip"))) {
                settings.put("sources jar", "yes");
            }
            if (hasPlugin(metadata, "maven-javadoc-plugin") && !"true".equals(values.get("maven.javadoc.skip"))) {
                settings.put("Javadoc jar", "yes");
            }
        }
        if (kind == Kind.PLATFORM) {
            List<String> managed = new ArrayList<>();
            for (Element dependency : children(child(child(pom, "dependencyManagement"), "dependencies"),
                    "dependency")) {
                String artifact = childText(dependency, "artifactId").orElse("");
                managed.add(moduleByArtifact.getOrDefault(artifact, artifact));
            }
            settings.put("managed modules", String.join(", ", managed.stream().sorted().toList()));
        }
        for (Element dependency : children(child(pom, "dependencies"), "dependency")) {
            List<String> excluded = new ArrayList<>();
            for (Element exclusion : children(child(dependency, "exclusions"), "exclusion")) {
                excluded.add(childText(exclusion, "groupId").orElse("") + ":"
                        + childText(exclusion, "artifactId").orElse(""));
            }
            if (!excluded.isEmpty()) {
                settings.put("exclusions of " + resolve(childText(dependency, "groupId").orElse(""), values) + ":"
                        + resolve(childText(dependency, "artifactId").orElse(""), values),
                        String.join(", ", excluded.stream().sorted().toList()));
            }
        }
        // The run profile's exec plugin is the Maven build's run task; the others (bench, load) are Maven's alone.
        for (Element profile : children(child(pom, "profiles"), "profile")) {
            if (!RUN_PROFILE.equals(childText(profile, "id").orElse(""))) {
                continue;
            }
            for (Element plugin : children(child(child(profile, "build"), "plugins"), "plugin")) {
                for (Element execution : children(child(plugin, "executions"), "execution")) {
                    childText(child(execution, "configuration"), "commandlineArgs")
                            .map(EXEC_MAIN_CLASS::matcher)
                            .filter(Matcher::find)
                            .ifPresent(main -> settings.put("main class", main.group("main")));
                }
            }
        }
        return settings;
    }

    /** The {@code <configuration>} of a plugin in the pom's {@code <pluginManagement>}, or null. */
    private static Element pluginConfiguration(Element pom, String artifactId) {
        Element management = child(child(pom, "build"), "pluginManagement");
        for (Element plugin : children(child(management, "plugins"), "plugin")) {
            if (artifactId.equals(childText(plugin, "artifactId").orElse(""))) {
                return child(plugin, "configuration");
            }
        }
        return null;
    }

    /** Whether the pom's {@code <build><plugins>} runs the plugin. */
    private static boolean hasPlugin(Element pom, String artifactId) {
        return children(child(child(pom, "build"), "plugins"), "plugin").stream()
                .anyMatch(plugin -> artifactId.equals(childText(plugin, "artifactId").orElse("")));
    }

    /** The {@code groupId:artifactId} of each of the project's own {@code <dependencies>}, with its usage. */
    private static Map<String, Usage> dependencies(Element project, Map<String, String> values) {
        Map<String, Usage> dependencies = new LinkedHashMap<>();
        for (Element dependency : children(child(project, "dependencies"), "dependency")) {
            String coordinates = resolve(childText(dependency, "groupId").orElse(""), values)
                    + ":" + resolve(childText(dependency, "artifactId").orElse(""), values);
            Usage usage = switch (childText(dependency, "scope").orElse("compile")) {
                case "test" -> Usage.TEST;
                case "runtime" -> Usage.RUNTIME;
                case "provided" -> Usage.PROVIDED;
                default -> Usage.COMPILE;
            };
            dependencies.merge(coordinates, usage, Usage::wider);
        }
        return dependencies;
    }

    private static String resolve(String text, Map<String, String> values) {
        Matcher placeholder = PLACEHOLDER.matcher(text);
        return placeholder.replaceAll(match -> Matcher.quoteReplacement(
                values.getOrDefault(match.group(1), match.group())));
    }

    /** Parses a pom with a parser that refuses DOCTYPEs, so no entity in it is ever expanded or fetched. */
    private static Element parse(Path pom) throws IOException {
        try {
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setNamespaceAware(true);
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            factory.setXIncludeAware(false);
            factory.setExpandEntityReferences(false);
            return factory.newDocumentBuilder().parse(pom.toFile()).getDocumentElement();
        } catch (ParserConfigurationException e) {
            throw new IllegalStateException("the JDK's XML parser cannot be configured securely", e);
        } catch (SAXException e) {
            throw new IllegalArgumentException("expected a well-formed pom without DOCTYPE: " + pom, e);
        }
    }

    private static Element child(Element parent, String name) {
        List<Element> found = children(parent, name);
        return found.isEmpty() ? null : found.get(0);
    }

    private static Optional<String> childText(Element parent, String name) {
        return Optional.ofNullable(child(parent, name)).map(MavenBuild::text);
    }

    /** The child elements of {@code parent} named {@code name} (any name if null); none if parent is null. */
    private static List<Element> children(Element parent, String name) {
        List<Element> children = new ArrayList<>();
        if (parent == null) {
            return children;
        }
        for (Node node = parent.getFirstChild(); node != null; node = node.getNextSibling()) {
            if (node instanceof Element element && (name == null || name.equals(element.getLocalName()))) {
                children.add(element);
            }
        }
        return children;
    }

    private static String text(Element element) {
        return element.getTextContent().strip();
    }
}
