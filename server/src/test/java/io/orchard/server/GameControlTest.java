package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.server.sim.Phase;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.LongFunction;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Who controls the game, on a real server over real sockets: a client that presented the operator
 * token starts, pauses and resumes it; the program that embeds the server does so without any
 * token; everyone else is refused with {@code forbidden} while the game goes on, its agents
 * missing no tick.
 */
class GameControlTest {

    private static final String OPERATOR = "op-7f3a9c21";

    private final List<AutoCloseable> open = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = open.size() - 1; i >= 0; i--) {
            open.get(i).close();
        }
    }

    private WorldServer started(WorldServer.Builder builder) throws IOException {
        WorldServer server = builder.start();
        open.add(server);
        return server;
    }

    /** A lockstep game that outlasts any test, so that its ticks run as fast as its agent ends its turns. */
    private static WorldServer.Builder lockstep() {
        return WorldServer.builder().port(0).seed(11).clock(ClockMode.LOCKSTEP).timeLimit(100_000);
    }

    /** An agent that ends its turn as soon as each tick begins, and keeps the number of every tick it was told of. */
    private final class Player {
        final List<Long> ticks = new CopyOnWriteArrayList<>();
        final ProtocolConnection connection;

        Player(int port) throws Exception {
            connection = ProtocolConnection.connect("127.0.0.1", port, Role.AGENT, "player", message -> {
                if (message instanceof TickMessage tick) {
                    ticks.add(tick.tick());
                    try {
                        send(seq -> new EndTurnMessage(seq, tick.tick()));
                    } catch (IOException e) {
                        // the connection closed: the test is over
                    }
                }
            });
            open.add(connection);
            Reply registered = connection.request(seq -> new RegisterMessage(seq, "Guppy", WorldServerTest.BODY, null))
                    .get(10, TimeUnit.SECONDS);
            assertThat(registered).isInstanceOf(RegisteredMessage.class);
        }

        private void send(LongFunction<? extends ClientMessage> message) throws IOException {
            connection.send(message);
        }

        long last() {
            return ticks.isEmpty() ? -1 : ticks.get(ticks.size() - 1);
        }

        /** Waits until the game has gone {@code more} ticks past the latest one told. */
        void awaitTicks(int more) {
            long target = last() + more;
            await(() -> last() >= target, "tick " + target + " (the agent is at tick " + last() + ")");
        }

        /** Every tick from the first the agent was told of to the last, each once and in order. */
        void assertMissedNone() {
            List<Long> told = List.copyOf(ticks);
            assertThat(told).isNotEmpty();
            for (int i = 0; i < told.size(); i++) {
                assertThat(told.get(i)).as("tick %d told to the agent", i).isEqualTo(told.get(0) + i);
            }
        }
    }

    private ProtocolConnection client(WorldServer server, Role role, String operatorToken) throws IOException {
        ProtocolConnection connection = ProtocolConnection.connect("127.0.0.1", server.port(), role, "test", null,
                operatorToken, message -> { });
        open.add(connection);
        return connection;
    }

    private static Reply control(ProtocolConnection client, GameCommand command) throws Exception {
        return client.request(seq -> new GameControlMessage(seq, command)).get(10, TimeUnit.SECONDS);
    }

    private static void await(BooleanSupplier condition, String what) {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!condition.getAsBoolean()) {
            assertThat(System.nanoTime()).as("waiting for %s", what).isLessThan(end);
            Thread.onSpinWait();
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError("interrupted waiting for " + what, e);
            }
        }
    }

    /** Asserts that no tick begins for a while: the game is paused, or waits. */
    private static void assertStill(Player player) throws InterruptedException {
        Thread.sleep(100); // a tick already under way when the game paused may still be told
        long before = player.last();
        Thread.sleep(400);
        assertThat(player.last()).as("ticks while the game is paused").isEqualTo(before);
    }

    @Test
    void aSpectatorsPauseIsForbiddenAndTheGameGoesOnWithoutAnAgentMissingATick() throws Exception {
        WorldServer server = started(lockstep().operatorToken(OPERATOR));
        Player player = new Player(server.port());
        player.awaitTicks(5);
        ProtocolConnection spectator = client(server, Role.VIEWER, null);

        Reply refused = control(spectator, GameCommand.PAUSE);
        Reply agentsToo = control(player.connection, GameCommand.PAUSE);

        assertThat(refused).isInstanceOfSatisfying(ErrorMessage.class, error -> {
            assertThat(error.code()).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(error.text()).contains("operator token");
        });
        assertThat(agentsToo).isInstanceOfSatisfying(ErrorMessage.class,
                error -> assertThat(error.code()).isEqualTo(ErrorCode.FORBIDDEN));
        player.awaitTicks(50);
        assertThat(server.phase()).isEqualTo(Phase.RUNNING);
        player.assertMissedNone();
        assertThat(spectator.isOpen()).isTrue();
    }

    @Test
    void theOperatorPausesAndResumesTheGame() throws Exception {
        WorldServer server = started(lockstep().operatorToken(OPERATOR));
        Player player = new Player(server.port());
        player.awaitTicks(5);
        ProtocolConnection operator = client(server, Role.VIEWER, OPERATOR);

        Reply paused = control(operator, GameCommand.PAUSE);

        assertThat(paused).isInstanceOfSatisfying(ActionResultMessage.class,
                result -> assertThat(result.outcome()).isEqualTo(Outcome.ACCEPTED));
        assertThat(server.phase()).isEqualTo(Phase.PAUSED);
        assertStill(player);
        assertThat(control(operator, GameCommand.PAUSE)).isInstanceOfSatisfying(ActionResultMessage.class,
                result -> assertThat(result.reason()).isEqualTo("the game is not running"));

        assertThat(control(operator, GameCommand.RESUME)).isInstanceOfSatisfying(ActionResultMessage.class,
                result -> assertThat(result.outcome()).isEqualTo(Outcome.ACCEPTED));
        player.awaitTicks(20);
        player.assertMissedNone();
    }

    @Test
    void theOperatorStartsAGameThatWaitsForMoreAgents() throws Exception {
        WorldServer server = started(lockstep().waitFor(3).operatorToken(OPERATOR));
        Player player = new Player(server.port());
        ProtocolConnection operator = client(server, Role.AGENT, OPERATOR);
        assertThat(server.phase()).isEqualTo(Phase.WAITING);

        assertThat(control(operator, GameCommand.START)).isInstanceOfSatisfying(ActionResultMessage.class,
                result -> assertThat(result.outcome()).isEqualTo(Outcome.ACCEPTED));

        player.awaitTicks(10);
        player.assertMissedNone();
    }

    @Test
    void aWrongOperatorTokenIsRefusedAtTheHandshake() throws Exception {
        WorldServer server = started(lockstep().operatorToken(OPERATOR));

        assertThatThrownBy(() -> client(server, Role.VIEWER, OPERATOR + "x")).isInstanceOf(IOException.class)
                .hasMessageContaining("unauthorized: wrong operator token");
    }

    @Test
    void withoutAnOperatorTokenNoClientControlsTheGameButTheEmbeddingProgramDoes() throws Exception {
        WorldServer server = started(lockstep().waitFor(3));
        Player player = new Player(server.port());
        ProtocolConnection viewer = client(server, Role.VIEWER, null);

        assertThat(control(viewer, GameCommand.START)).isInstanceOfSatisfying(ErrorMessage.class, error -> {
            assertThat(error.code()).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(error.text()).contains("this server has no operator token");
        });
        assertThat(server.phase()).isEqualTo(Phase.WAITING);
        assertThatThrownBy(() -> client(server, Role.VIEWER, OPERATOR)).isInstanceOf(IOException.class)
                .hasMessageContaining("unauthorized: this server has no operator token");

        server.startGame();
        server.pauseGame();
        await(() -> server.phase() == Phase.PAUSED, "the pause");
        assertStill(player);
        server.resumeGame();
        player.awaitTicks(10);
        server.togglePause();
        await(() -> server.phase() == Phase.PAUSED, "the pause by toggling");
        assertStill(player);
        server.togglePause();
        player.awaitTicks(10);
        assertThat(server.phase()).isEqualTo(Phase.RUNNING);
        player.assertMissedNone();
    }

    @Test
    void theOperatorTokenMustNotBeEmptyNorTheTokenEveryClientHolds() {
        assertThatThrownBy(() -> WorldServer.builder().operatorToken("")).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("operator token must not be empty");
        assertThatThrownBy(() -> WorldServer.builder().token("same").operatorToken("same"))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("must differ from the token");
        assertThatThrownBy(() -> WorldServer.builder().operatorToken("same").token("same"))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("must differ from the token");
    }
}
