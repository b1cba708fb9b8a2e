package io.orchard.viewer.live;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.Phase;
import java.io.IOException;
import java.time.Duration;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The viewer's Space and G against a real server with an operator token: the operator's pause and
 * continue reach the game and are told; anyone else's are not sent, and the viewer says whose they
 * are; a pause from elsewhere is found out from the server's answer.
 */
class GameControlsTest {

    private static final String OPERATOR = "op-3e8b";

    private final BlockingQueue<String> told = new LinkedBlockingQueue<>();
    private WorldServer server;
    private ServerLink link;

    @BeforeEach
    void startARunningGame() throws IOException {
        server = WorldServer.builder().port(0).seed(1).clock(ClockMode.REALTIME).operatorToken(OPERATOR).start();
        server.startGame();
    }

    @AfterEach
    void stop() {
        if (link != null) {
            link.close();
        }
        server.close();
    }

    private GameControls controls(String operatorToken) throws InterruptedException {
        CountDownLatch connected = new CountDownLatch(1);
        GameControls[] controls = new GameControls[1];
        link = new ServerLink("127.0.0.1", server.port(), null, operatorToken, null, new ServerLink.Listener() {
            @Override
            public void connected() {
                connected.countDown();
            }

            @Override
            public void received(ServerMessage message) {
                if (message instanceof TickMessage && controls[0] != null) {
                    controls[0].ticked();
                }
            }

            @Override
            public void ended(String reason, Duration retryIn) {
                told.add("ended: " + reason);
            }
        });
        controls[0] = new GameControls(link, operatorToken != null, new GameControls.Notes() {
            @Override
            public void event(String text) {
                told.add("event: " + text);
            }

            @Override
            public void problem(String text) {
                told.add("problem: " + text);
            }
        });
        link.start();
        assertThat(connected.await(20, TimeUnit.SECONDS)).as("connected").isTrue();
        await(link::isConnected, "the connection");
        return controls[0];
    }

    private String nextTold() throws InterruptedException {
        String line = told.poll(20, TimeUnit.SECONDS);
        assertThat(line).as("what the viewer told").isNotNull();
        return line;
    }

    private static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!condition.getAsBoolean()) {
            assertThat(System.nanoTime()).as("waiting for %s", what).isLessThan(end);
            Thread.sleep(10);
        }
    }

    @Test
    void theOperatorsSpacePausesAndContinuesTheGame() throws Exception {
        GameControls controls = controls(OPERATOR);

        controls.togglePause();
        assertThat(nextTold()).isEqualTo("event: you paused the game");
        assertThat(server.phase()).isEqualTo(Phase.PAUSED);

        controls.togglePause();
        assertThat(nextTold()).isEqualTo("event: you continued the game");
        assertThat(server.phase()).isEqualTo(Phase.RUNNING);
    }

    @Test
    void withoutTheOperatorTokenNothingIsSentAndTheViewerSaysWhoseTheKeysAre() throws Exception {
        GameControls controls = controls(null);

        controls.togglePause();
        controls.start();

        assertThat(nextTold()).isEqualTo("problem: Pausing the game " + GameControls.NOT_OPERATOR);
        assertThat(nextTold()).isEqualTo("problem: Starting the game " + GameControls.NOT_OPERATOR);
        assertThat(GameControls.NOT_OPERATOR).contains("--operator-token", "ORCHARD_OPERATOR_TOKEN");
        Thread.sleep(200);
        assertThat(server.phase()).isEqualTo(Phase.RUNNING);
    }

    @Test
    void aGamePausedElsewhereIsFoundOutFromTheRefusalAndTheNextPressContinuesIt() throws Exception {
        GameControls controls = controls(OPERATOR);
        server.pauseGame();
        await(() -> server.phase() == Phase.PAUSED, "the console's pause");

        controls.togglePause();
        assertThat(nextTold()).isEqualTo("problem: pausing the game refused: the game is not running");
        controls.togglePause();

        assertThat(nextTold()).isEqualTo("event: you continued the game");
        assertThat(server.phase()).isEqualTo(Phase.RUNNING);
    }
}
