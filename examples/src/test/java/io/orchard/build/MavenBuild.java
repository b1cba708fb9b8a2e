package io.orchard.build;

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
 * The Maven build as its poms declare it: the root pom's modules and properties, and for each
 * module its coordinates and dependencies, including those every module inherits from the root.
 *
 * @param modules    the root pom's {@code <modules>}, in order
 * @param properties the root pom's {@code <properties>}
 * @param builds     each module's build, by module name
 */
record MavenBuild(List<String> modules, Map<String, String> properties, Map<String, ModuleBuild> builds) {

    private static final Pattern PLACEHOLDER = Pattern.compile("\\$\\{([^}]+)}");

    MavenBuild {
        modules = List.copyOf(modules);
        properties = Map.copyOf(properties);
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
            Map<String, String> values = new HashMap<>(properties);
            values.put("project.groupId", childText(pom, "groupId").orElse(groupId));
            values.put("project.version", childText(pom, "version").orElse(version));

            // A module inherits the root's <dependencies>; its own declaration of one replaces it.
            Map<String, Usage> declared = dependencies(parent, values);
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
            builds.put(entry.getKey(), new ModuleBuild(entry.getKey(), values.get("project.groupId"),
                    values.get("project.version"), onModules, onLibraries));
        }
        return new MavenBuild(modules, properties, builds);
    }

    /** The {@code groupId:artifactId} of each of the project's own {@code <dependencies>}, with its usage. */
    private static Map<String, Usage> dependencies(Element project, Map<String, String> values) {
        Map<String, Usage> dependencies = new LinkedHashMap<>();
        for (Element dependency : children(child(project, "dependencies"), "dependency")) {
            String coordinates = resolve(childText(dependency, "groupId").orElse(""), values)
                    + ":" + resolve(childText(dependency, "artifactId").orElse(""), values);
            Usage usage = "test".equals(childText(dependency, "scope").orElse("compile")) ? Usage.TEST : Usage.MAIN;
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
