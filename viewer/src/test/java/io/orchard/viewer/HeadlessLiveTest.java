package io.orchard.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.WorldServer;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The headless viewer against a live server (started here on port 0, its game waiting for more
 * agents so that it stays still): a screenshot of the world as it is, and a watchdog that ends a
 * run that waits too long with status 1.
 */
class HeadlessLiveTest {

    @TempDir
    static Path dir;
    static WorldServer server;
    static ProtocolConnection agent;

    @BeforeAll
    static void startAServerWithOneAgent() throws Exception {
        ViewerProcess.xvfbRun();
        server = WorldServer.builder().port(0).seed(GameFixture.SEED).clock(ClockMode.REALTIME).waitFor(5)
                .placement((name, radius) -> new Vec3(0, 0, 0)).start();
        agent = ProtocolConnection.connect("127.0.0.1", server.port(), Role.AGENT, "live-test", message -> { });
        agent.request(seq -> new RegisterMessage(seq, "Bunny", GameFixture.WALKER_BODY, ModelSpec.bundled("bunny")))
                .get(10, TimeUnit.SECONDS);
    }

    @AfterAll
    static void stopTheServer() {
        agent.close();
        server.close();
    }

    @Test
    void aScreenshotOfALiveWorldIsWrittenAndTheRunEnds() throws Exception {
        ViewerProcess.Result run = ViewerProcess.run(dir, "--host", "127.0.0.1", "--port",
                String.valueOf(server.port()), "--headless", "--size", "640x360", "--follow", "Bunny",
                "--screenshot", "live.png");

        assertThat(run.exit()).as("exit status; output:%n%s", run.output()).isZero();
        assertThat(run.output()).contains("wrote live.png (640x360, t=0.00 s, 1 agents");
        Frame frame = Frame.read(dir.resolve("live.png"), new Vec3(0, 10, 10), new Vec3(0, 0, 0));
        assertThat(frame.distinctColours()).isGreaterThan(40);
    }

    @Test
    void theWatchdogEndsARunThatWaitsTooLongWithStatusOne() throws Exception {
        ViewerProcess.Result run = ViewerProcess.run(dir, "--host", "127.0.0.1", "--port",
                String.valueOf(server.port()), "--headless", "--size", "320x180", "--screenshot", "never.png",
                "--at", "60", "--timeout", "3");

        assertThat(run.exit()).as("exit status; output:%n%s", run.output()).isEqualTo(1);
        assertThat(run.output()).contains("watchdog: the headless run did not finish within 3 s");
        assertThat(dir.resolve("never.png")).doesNotExist();
    }

    @Test
    void aServerThatIsNotThereEndsTheRunWithStatusOne() throws Exception {
        ViewerProcess.Result run = ViewerProcess.run(dir, "--host", "127.0.0.1", "--port", "1", "--headless",
                "--size", "320x180", "--screenshot", "nothing.png");

        assertThat(run.exit()).as("exit status; output:%n%s", run.output()).isEqualTo(1);
        assertThat(run.output()).contains("cannot connect to the server at 127.0.0.1:1");
    }
}
