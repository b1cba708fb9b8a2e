package io.orchard.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.cli.UsageException;
import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.state.Shot;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ViewerOptionsTest {

    static ViewerOptions parse(String line) throws UsageException {
        return ViewerOptions.parse(line.isBlank() ? List.of() : Arrays.asList(line.split(" ")));
    }

    @Test
    void withoutOptionsItWatchesTheLocalServerInAWindow() throws UsageException {
        ViewerOptions options = parse("");

        assertThat(options.host()).isEqualTo("localhost");
        assertThat(options.port()).isEqualTo(7557);
        assertThat(options.headless()).isFalse();
        assertThat(options.width()).isEqualTo(1280);
        assertThat(options.height()).isEqualTo(720);
        assertThat(options.shadows()).isFalse();
        assertThat(options.hud()).isTrue();
    }

    @Test
    void screenshotsPairWithTheirTimesInOrder() throws UsageException {
        ViewerOptions options = parse("--replay game.ndjson --headless --size 640x360 --screenshot a.png --at 12.5 "
                + "--screenshot b.png --at 3 --camera 1,2,3 --look-at 0,0,-5 --hud off");

        assertThat(options.shots()).containsExactly(new Shot(12.5, Path.of("a.png")), new Shot(3, Path.of("b.png")));
        assertThat(options.camera()).isEqualTo(new Vec3(1, 2, 3));
        assertThat(options.lookAt()).isEqualTo(new Vec3(0, 0, -5));
        assertThat(options.hud()).isFalse();
        assertThat(options.timeout()).as("a replay waits for no server").isEqualTo(ViewerOptions.BASE_TIMEOUT);
    }

    @Test
    void aLiveRunsWatchdogAllowsForTheTimeItWaitsFor() throws UsageException {
        assertThat(parse("--headless --screenshot a.png --at 100").timeout()).isEqualTo(160);
        assertThat(parse("--headless --screenshot a.png --at 100 --timeout 5").timeout()).isEqualTo(5);
    }

    @Test
    void helpIsNotAnError() throws UsageException {
        assertThat(parse("--help")).isNull();
        assertThat(ViewerOptions.help()).contains("--replay FILE", "--screenshot FILE", "--every SECONDS",
                "Exit status");
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
            "--headless                                          | --headless has nothing to do",
            "--screenshot a.png                                  | --screenshot and --every need --headless",
            "--headless --screenshot a.png --at 1 --at 2          | give one --at per --screenshot: 1 --screenshot and 2",
            "--headless --every 2                                 | --every needs --out DIR",
            "--headless --out shots                               | --out and --until go with --every",
            "--replay game.ndjson --port 7000                     | --replay plays a file",
            "--speed 2                                            | --speed is for --replay",
            "--replay g.ndjson --speed 1000                       | --speed must be 0.0625 to 64.0, was 1000",
            "--size 1280                                          | --size must be WIDTHxHEIGHT in pixels",
            "--size 10x10                                         | each 64 to 8192",
            "--headless --screenshot a.png --at soon              | --at must be a number of seconds, 0 or more, was 'soon'",
            "--headless --screenshot a.png --camera 1,2           | --camera must be three numbers X,Y,Z",
            "--camera 1,2,3                                       | --camera and --look-at place the headless camera",
            "--follow 9lives                                      | --follow must be an agent's name",
            "--shadows maybe                                      | --shadows must be one of on, off, was 'maybe'",
            "--port 0                                             | --port must be 1 to 65535, was 0",
            "--headless --measure 5 --screenshot a.png            | --measure renders as fast as it can",
            "--fps 3                                              | unknown option --fps"
    })
    void badCommandLinesAreRefusedNamingTheOption(String line, String message) {
        assertThatThrownBy(() -> parse(line.strip())).isInstanceOf(UsageException.class).hasMessageContaining(message);
    }
}
