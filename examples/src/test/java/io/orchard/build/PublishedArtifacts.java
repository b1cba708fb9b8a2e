package io.orchard.build;

import io.orchard.build.ModuleBuild.Kind;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The files Orchard publishes, where the reactor leaves them: the parent pom, each library's pom,
 * jar, sources jar and Javadoc jar, and the BOM. What {@code mvn install} would copy into a local
 * repository, and {@link Artifact#installInto} does.
 */
final class PublishedArtifacts {

    private static final Pattern ARTIFACT_ID = Pattern.compile("<artifactId>(?<id>[^<]+)</artifactId>");

    private PublishedArtifacts() {
    }

    /**
     * One file of a published artifact.
     *
     * @param classifier {@code null} for the main file
     * @param extension  {@code pom} or {@code jar}
     * @param file       where the build left it
     */
    record Artifact(String group, String artifact, String version, String classifier, String extension,
            Path file) {

        /** Where a Maven repository keeps it: {@code group/as/path/artifact/version/artifact-version[-classifier].ext}. */
        Path pathIn(Path repository) {
            return repository.resolve(group.replace('.', '/')).resolve(artifact).resolve(version)
                    .resolve(artifact + "-" + version + (classifier == null ? "" : "-" + classifier) + "." + extension);
        }

        void installInto(Path repository) {
            try {
                Path target = pathIn(repository);
                Files.createDirectories(target.getParent());
                Files.copy(file, target, StandardCopyOption.REPLACE_EXISTING);
            } catch (IOException e) {
                throw new UncheckedIOException("cannot install " + file + " into " + repository, e);
            }
        }
    }

    /**
     * The published files of the build in {@code root}; each must exist, as it does once the
     * reactor has packaged the modules.
     */
    static List<Artifact> of(Path root, MavenBuild maven) throws IOException {
        List<Artifact> artifacts = new ArrayList<>();
        String group = maven.builds().get("protocol").group();
        String version = maven.builds().get("protocol").version();
        Matcher parent = ARTIFACT_ID.matcher(Files.readString(root.resolve("pom.xml")));
        if (!parent.find()) {
            throw new IllegalArgumentException("expected an <artifactId> in " + root.resolve("pom.xml"));
        }
        artifacts.add(existing(new Artifact(group, parent.group("id"), version, null, "pom", root.resolve("pom.xml"))));
        for (ModuleBuild module : maven.builds().values()) {
            Path dir = root.resolve(module.name());
            if (module.kind() == Kind.PROGRAM) {
                continue;
            }
            artifacts.add(existing(new Artifact(module.group(), module.artifact(), module.version(), null, "pom",
                    dir.resolve("pom.xml"))));
            if (module.kind() == Kind.LIBRARY) {
                String base = module.artifact() + "-" + module.version();
                for (String classifier : new String[] {null, "sources", "javadoc"}) {
                    Path jar = dir.resolve("target").resolve(base + (classifier == null ? "" : "-" + classifier)
                            + ".jar");
                    artifacts.add(existing(new Artifact(module.group(), module.artifact(), module.version(),
                            classifier, "jar", jar)));
                }
            }
        }
        return artifacts;
    }

    private static Artifact existing(Artifact artifact) {
        if (!Files.isRegularFile(artifact.file())) {
            throw new IllegalStateException("expected " + artifact.file() + ", which the reactor packages before the "
                    + "integration tests: run them with ./mvnw verify");
        }
        return artifact;
    }
}
