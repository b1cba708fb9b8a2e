package io.orchard.examples.firstagent;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The tutorial's own edit (step 6), made as it says, gives an agent that compiles and that step
 * 8's {@link FirstAgentTest} still accepts: under 40 lines.
 */
class TutorialTest {

    private static final Path TUTORIAL = Path.of("..", "docs", "tutorial.md");
    private static final Path SOURCE = Path.of("src/main/java/io/orchard/examples/firstagent/FirstAgent.java");
    private static final Pattern JAVA_BLOCK = Pattern.compile("```java\\n(.*?)```", Pattern.DOTALL);

    @TempDir
    Path dir;

    @Test
    void stepSixsEditCompilesAndKeepsFirstAgentUnderFortyLines() throws IOException {
        String tutorial = Files.readString(TUTORIAL, StandardCharsets.UTF_8);
        String stepSix = tutorial.substring(tutorial.indexOf("## 6."), tutorial.indexOf("## 7."));
        assertThat(stepSix).contains("Replace the first `if` of `decide`");
        Matcher block = JAVA_BLOCK.matcher(stepSix);
        assertThat(block.find()).as("step 6 shows its edit as Java").isTrue();

        List<String> edited = replaceFirstIfOfDecide(Files.readAllLines(SOURCE, StandardCharsets.UTF_8),
                block.group(1).lines().toList());

        assertThat(edited.size()).as("lines of FirstAgent.java after step 6").isLessThan(40);
        Path file = dir.resolve("src/io/orchard/examples/firstagent/FirstAgent.java");
        Files.createDirectories(file.getParent());
        Files.write(file, edited, StandardCharsets.UTF_8);
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        StringWriter errors = new StringWriter();
        boolean compiled = javac.getTask(errors, null, null, List.of("-d", dir.resolve("classes").toString(),
                "-cp", System.getProperty("java.class.path")), null,
                javac.getStandardFileManager(null, null, StandardCharsets.UTF_8).getJavaFileObjects(file.toFile()))
                .call();
        assertThat(compiled).as("FirstAgent.java after step 6 compiles: %s", errors).isTrue();
    }

    /** The source with the first {@code if} statement of {@code decide}, up to its closing brace, replaced. */
    private static List<String> replaceFirstIfOfDecide(List<String> source, List<String> replacement) {
        int decide = indexOf(source, 0, line -> line.contains(" void decide("));
        int start = indexOf(source, decide, line -> line.strip().startsWith("if ("));
        String indent = source.get(start).substring(0, source.get(start).indexOf("if ("));
        int end = indexOf(source, start, line -> line.equals(indent + "}"));
        List<String> edited = new ArrayList<>(source.subList(0, start));
        edited.addAll(replacement);
        edited.addAll(source.subList(end + 1, source.size()));
        return edited;
    }

    private static int indexOf(List<String> lines, int from, java.util.function.Predicate<String> wanted) {
        for (int i = from; i < lines.size(); i++) {
            if (wanted.test(lines.get(i))) {
                return i;
            }
        }
        throw new AssertionError("FirstAgent.java has no line as expected after line " + (from + 1));
    }
}
