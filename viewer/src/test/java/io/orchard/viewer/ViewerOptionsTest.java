package io.orchard.viewer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.value.Vec3;
import io.orchard.viewer.state.Shot;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import picocli.CommandLine.ParameterException;

class ViewerOptionsTest {

    static ViewerOptions parse(String line) {
        return ViewerCommand.parse(line.isBlank() ? List.of() : Arrays.asList(line.split(" ")));
    }

    @Test
    void withoutOptionsItWatchesTheLocalServerInAWindow() {
        ViewerOptions options = parse("");

        assertThat(options.host()).isEqualTo("localhost");
        assertThat(options.port()).isEqualTo(7557);
        assertThat(options.headless()).isFalse();
        assertThat(options.width()).isEqualTo(1280);
        assertThat(options.height()).isEqualTo(720);
        assertThat(options.shadows()).isFalse();
        assertThat(options.hud()).isTrue();
        assertThat(options.reconnect()).as("connects again when the connection ends").isTrue();
    }

    @Test
    void theOperatorTokenIsPassedOnAndReconnectingCanBeTurnedOff() {
        ViewerOptions options = parse("--operator-token op-s3cret --no-reconnect");

        assertThat(options.operatorToken()).isEqualTo("op-s3cret");
        assertThat(options.reconnect()).isFalse();
        assertThat(ViewerMain.help()).contains("--operator-token=SECRET", "ORCHARD_OPERATOR_TOKEN", "--no-reconnect");
    }

    @Test
    void screenshotsPairWithTheirTimesInOrder() {
        ViewerOptions options = parse("--replay game.ndjson --headless --size 640x360 --screenshot a.png --at 12.5 "
                + "--screenshot b.png --at 3 --camera 1,2,3 --look-at 0,0,-5 --hud off");

        assertThat(options.shots()).containsExactly(new Shot(12.5, Path.of("a.png")), new Shot(3, Path.of("b.png")));
        assertThat(options.camera()).isEqualTo(new Vec3(1, 2, 3));
        assertThat(options.lookAt()).isEqualTo(new Vec3(0, 0, -5));
        assertThat(options.hud()).isFalse();
        assertThat(options.timeout()).as("a replay waits for no server").isEqualTo(ViewerOptions.BASE_TIMEOUT);
    }

    @Test
    void aLiveRunsWatchdogAllowsForTheTimeItWaitsFor() {
        assertThat(parse("--headless --screenshot a.png --at 100").timeout()).isEqualTo(160);
        assertThat(parse("--headless --screenshot a.png --at 100 --timeout 5").timeout()).isEqualTo(5);
    }

    @Test
    void helpIsNotAnError() {
        assertThat(parse("--help")).isNull();
        assertThat(ViewerMain.help()).contains("--replay=FILE", "--screenshot=FILE", "--every=SECONDS",
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
            "--replay game.ndjson --operator-token s3cret         | --replay plays a file; --operator-token and --no-reconnect are for a live server",
            "--replay game.ndjson --no-reconnect                  | --replay plays a file; --operator-token and --no-reconnect are for a live server",
            "--speed 2                                            | --speed is for --replay",
            "--replay g.ndjson --speed 1000                       | option '--speed': '1000' is out of range (expected 0.0625-64",
            "--size 1280                                          | option '--size': '1280' is not a size (expected WIDTHxHEIGHT in pixels",
            "--size 10x10                                         | option '--size': '10x10' is not a size (expected WIDTHxHEIGHT in pixels, each 64 to 8192",
            "--headless --screenshot a.png --at soon              | option '--at' (SECONDS): 'soon' is not a number (expected a number of seconds, 0 or more)",
            "--headless --screenshot a.png --camera 1,2           | option '--camera': '1,2' is not a point (expected three numbers X,Y,Z",
            "--camera 1,2,3                                       | --camera and --look-at place the headless camera",
            "--follow 9lives                                      | option '--follow': '9lives' is not an agent's name",
            "--shadows maybe                                      | option '--shadows': 'maybe' is neither on nor off (expected on or off)",
            "--port 0                                             | option '--port': '0' is out of range (expected a port 1-65535)",
            "--headless --measure 5 --screenshot a.png            | --measure renders as fast as it can",
            "--fps 3                                              | Unknown options: '--fps', '3'"
    })
    void badCommandLinesAreRefusedNamingTheOption(String line, String message) {
        assertThatThrownBy(() -> parse(line.strip())).isInstanceOf(ParameterException.class).hasMessageContaining(message);
    }
}
