package io.orchard.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The command line's answers that need no display. */
class ViewerMainTest {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String... args) {
        return ViewerMain.run(List.of(args), new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    @Test
    void helpPrintsTheOptionsAndExitsZero() {
        assertThat(run("--help")).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).startsWith("Usage: orchard viewer [OPTIONS]")
                .contains("--headless", "--replay=FILE");
    }

    @Test
    void aBadCommandLineExitsTwoNamingTheOption() {
        assertThat(run("--size", "huge")).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8))
                .contains("orchard viewer: invalid value for option '--size': 'huge' is not a size (expected WIDTHxHEIGHT")
                .contains("./orchard viewer --help");
    }

    @Test
    void aRecordingThatCannotBeReadExitsOneSayingWhy(@TempDir Path dir) throws Exception {
        Path empty = Files.writeString(dir.resolve("empty.ndjson"), "");

        assertThat(run("--replay", empty.toString(), "--headless", "--screenshot", "x.png")).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("holds no WorldSnapshot line");
    }

    @Test
    void aCorruptRecordingIsNamedWithItsLineAndWhatIsWrong(@TempDir Path dir) throws Exception {
        Path corrupt = Files.write(dir.resolve("corrupt.ndjson"),
                new byte[] {'{', '"', 't', 'i', 'c', 'k', '"', ':', '0', '}', '\n', (byte) 0xff, (byte) 0xfe, ' ', 'x', '\n'});

        assertThat(run("--replay", corrupt.toString(), "--headless", "--screenshot", "x.png")).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8)).isEqualTo("orchard viewer: cannot replay " + corrupt
                + ": line 2 is not UTF-8 text (a malformed byte sequence at byte 1 of 4); 1 of its 2 lines could not"
                + " be read, and no WorldSnapshot line was found to start from" + System.lineSeparator());
    }

    @Test
    void aRenderErrorEndsTheRunWithStatusOneNotZero() throws Exception {
        ViewerOptions options = ViewerCommand.parse(List.of("--headless", "--screenshot", "x.png"));
        ViewerApp app = new ViewerApp(options, null, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));

        app.handleError("Failed to create display", new IllegalStateException("GLX: no visual"));

        assertThat(app.exitStatus().getNow(-1)).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8))
                .contains("orchard viewer: render failed: Failed to create display: GLX: no visual");
    }
}
