package io.orchard.build;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.build.ModuleBuild.Kind;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import javax.tools.DocumentationTool;
import javax.tools.ToolProvider;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every public and protected type and member of a published library has a doc comment, so that its
 * Javadoc jar documents all it shows. The Javadoc build itself fails on any other doclint warning
 * (HTML, references, syntax); this is the check of doclint's "missing" group it leaves out.
 */
class JavadocCoverageTest {

    static List<String> libraries() throws IOException {
        return MavenBuild.read(BuildDriftTest.repositoryRoot()).builds().values().stream()
                .filter(build -> build.kind() == Kind.LIBRARY)
                .map(ModuleBuild::name)
                .sorted()
                .toList();
    }

    @ParameterizedTest
    @MethodSource("libraries")
    void everyPublicTypeAndMemberHasADocComment(String module) {
        Path sources = BuildDriftTest.repositoryRoot().resolve(module).resolve("src/main/java");
        DocumentationTool javadoc = ToolProvider.getSystemDocumentationTool();
        StringWriter output = new StringWriter();

        boolean ran = javadoc.getTask(output, null, null, MissingComments.class, List.of(
                "-quiet", "-protected", "--source-path", sources.toString(), "-subpackages", "io.orchard",
                "--class-path", classpathWithout(module)), null).call();

        assertThat(ran).as("javadoc on %s: %s", sources, output).isTrue();
        assertThat(MissingComments.takeFound()).as("public and protected types and members of %s without a doc "
                + "comment", module).isEmpty();
    }

    /**
     * This JVM's class path less the module's own classes, which javadoc would otherwise read
     * instead of its sources when they are newer, and find no comments in.
     */
    private static String classpathWithout(String module) {
        String separator = java.io.File.pathSeparator;
        return Arrays.stream(System.getProperty("java.class.path", "").split(Pattern.quote(separator)))
                .filter(entry -> !entry.replace('\\', '/').matches(".*/" + Pattern.quote(module) + "/(target|build)/.*"))
                .collect(Collectors.joining(separator));
    }
}
