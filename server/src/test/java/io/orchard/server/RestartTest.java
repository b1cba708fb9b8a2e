package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.AgentRemovedMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.ErrorCode;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.NewGameMessage;
import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WelcomeMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.Outcome;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.Phase;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The operator's restart, on real servers over real sockets: the game ends, a new game of the seed
 * asked for waits on the same server and the same connections, and it is the game a new server of
 * that seed would play; whoever is not the operator cannot restart, a version 1 client is let go,
 * and a server that plays one game only says why it refuses.
 */
class RestartTest {

    private static final String OPERATOR = "op-restart-5e1d";

    @TempDir
    Path dir;

    private final List<AutoCloseable> open = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = open.size() - 1; i >= 0; i--) {
            open.get(i).close();
        }
    }

    private WorldServer started(long seed) throws IOException {
        WorldServer server = WorldServer.builder().port(0).seed(seed).clock(ClockMode.LOCKSTEP).timeLimit(100_000)
                .operatorToken(OPERATOR).start();
        open.add(server);
        return server;
    }

    /** A connection that keeps what it is told, in order, and in lockstep ends each tick's turn once told. */
    private final class Client {
        final BlockingQueue<ServerMessage> told = new LinkedBlockingQueue<>();
        final List<ServerMessage> skipped = new ArrayList<>();
        final ProtocolConnection connection;

        Client(WorldServer server, Role role, String operatorToken) throws IOException {
            connection = ProtocolConnection.connect("127.0.0.1", server.port(), role, "test", null, operatorToken,
                    told::add);
            open.add(connection);
        }

        /** The next message of this type, skipping others; fails after 10 s. */
        <T extends ServerMessage> T next(Class<T> type) throws InterruptedException {
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (true) {
                ServerMessage message = told.poll(Math.max(1, end - System.nanoTime()), TimeUnit.NANOSECONDS);
                assertThat(message).as("a %s within 10 s, after %s", type.getSimpleName(), skipped).isNotNull();
                if (type.isInstance(message)) {
                    return type.cast(message);
                }
                skipped.add(message);
            }
        }

        Reply request(GameControlMessage control) throws Exception {
            return connection.request(seq -> new GameControlMessage(seq, control.command(), control.seed()))
                    .get(10, TimeUnit.SECONDS);
        }

        RegisteredMessage register(String name) throws Exception {
            Reply reply = connection.request(seq -> new RegisterMessage(seq, name, WorldServerTest.BODY, null))
                    .get(10, TimeUnit.SECONDS);
            assertThat(reply).isInstanceOf(RegisteredMessage.class);
            connection.send(seq -> new PerceptionRequestMessage(seq, name, 1));
            connection.send(seq -> new EndTurnMessage(seq, 0)); // the setup turn
            return (RegisteredMessage) reply;
        }

        /**
         * Plays {@code ticks} ticks of a lockstep game from its start: each tick's perception kept, a move
         * every eighth tick to a place the tick number chooses, then the turn ended.
         */
        List<PerceptionMessage> play(String name, int ticks) throws Exception {
            List<PerceptionMessage> seen = new ArrayList<>();
            while (seen.size() < ticks) {
                PerceptionMessage perception = next(PerceptionMessage.class);
                seen.add(perception);
                long tick = perception.tick();
                if (tick % 8 == 0) {
                    Vec3 to = Vec3.ground(perception.position().x() + (tick % 16 == 0 ? 6 : -4),
                            perception.position().z() + 3);
                    connection.send(seq -> new MoveMessage(seq, name, null, to));
                }
                connection.send(seq -> new EndTurnMessage(seq, tick));
            }
            return seen;
        }
    }

    private static GameControlMessage restart(Long seed) {
        return new GameControlMessage(0, GameCommand.RESTART, seed);
    }

    @Test
    void theOperatorsRestartEndsTheGameAndTheNewGameIsTheOneANewServerOfTheSeedPlays() throws Exception {
        // What a new server of seed 12 shows a viewer and plays with Guppy
        WorldServer fresh = started(12);
        Client freshViewer = new Client(fresh, Role.VIEWER, null);
        WorldSnapshotMessage freshWorld = freshViewer.next(WorldSnapshotMessage.class);
        Client freshPlayer = new Client(fresh, Role.AGENT, null);
        RegisteredMessage freshGuppy = freshPlayer.register("Guppy");
        List<PerceptionMessage> freshGame = freshPlayer.play("Guppy", 60);

        // A server of seed 11, its game under way, restarted to seed 12
        WorldServer server = started(11);
        Client viewer = new Client(server, Role.VIEWER, null);
        viewer.next(WorldSnapshotMessage.class);
        Client player = new Client(server, Role.AGENT, OPERATOR);
        player.register("Guppy");
        player.play("Guppy", 25);
        assertThat(player.next(PerceptionMessage.class).tick()).isEqualTo(25);
        CompletableFuture<Reply> asked = player.connection.request(seq -> new GameControlMessage(seq,
                GameCommand.RESTART, 12L));
        player.connection.send(seq -> new EndTurnMessage(seq, 25)); // the tick in which it was asked ends
        Reply accepted = asked.get(10, TimeUnit.SECONDS);

        assertThat(accepted).isInstanceOfSatisfying(ActionResultMessage.class,
                result -> assertThat(result.outcome()).isEqualTo(Outcome.ACCEPTED));
        GameOverMessage over = player.next(GameOverMessage.class);
        assertThat(over.reason()).isEqualTo("restarted by the operator");
        assertThat(over.tick()).isEqualTo(26);
        assertThat(player.next(AgentRemovedMessage.class).agent()).isEqualTo("Guppy");
        assertThat(player.next(NewGameMessage.class)).isEqualTo(new NewGameMessage(0, 100_000));
        assertThat(viewer.next(GameOverMessage.class).reason()).isEqualTo("restarted by the operator");
        viewer.next(NewGameMessage.class);
        assertThat(viewer.next(WorldSnapshotMessage.class)).as("the new world, as a new server of its seed shows it")
                .isEqualTo(freshWorld);
        assertThat(server.seed()).isEqualTo(12);
        assertThat(server.phase()).isEqualTo(Phase.WAITING);

        RegisteredMessage guppy = player.register("Guppy");
        assertThat(guppy.position()).isEqualTo(freshGuppy.position());
        assertThat(guppy.seed()).isEqualTo(freshGuppy.seed());
        assertThat(player.play("Guppy", 60)).as("the game, perception for perception").isEqualTo(freshGame);
        assertThat(player.connection.isOpen()).isTrue();
    }

    @Test
    void aRestartWithoutASeedMakesTheSameWorldAgainAndAGameThatIsOverCanBeRestarted() throws Exception {
        WorldServer server = WorldServer.builder().port(0).seed(21).clock(ClockMode.LOCKSTEP).timeLimit(1)
                .tickRate(20).operatorToken(OPERATOR).start();
        open.add(server);
        Client viewer = new Client(server, Role.VIEWER, OPERATOR);
        WorldSnapshotMessage first = viewer.next(WorldSnapshotMessage.class);
        Client player = new Client(server, Role.AGENT, null);
        player.register("Bunny");
        player.play("Bunny", 20);
        List<Score> ranking = server.gameOver().get(10, TimeUnit.SECONDS);
        assertThat(ranking).extracting(Score::agent).containsExactly("Bunny");

        assertThat(viewer.request(restart(null))).isInstanceOfSatisfying(ActionResultMessage.class,
                result -> assertThat(result.outcome()).isEqualTo(Outcome.ACCEPTED));

        viewer.next(NewGameMessage.class);
        WorldSnapshotMessage again = viewer.next(WorldSnapshotMessage.class);
        assertThat(again).isEqualTo(first);
        assertThat(again.scores()).isEmpty();
        assertThat(server.gameOver()).as("the new game's").isNotDone();
        player.next(NewGameMessage.class);
        player.register("Bunny");
        assertThat(player.play("Bunny", 20)).hasSize(20);
        assertThat(server.gameOver().get(10, TimeUnit.SECONDS)).extracting(Score::agent).containsExactly("Bunny");
    }

    @Test
    void whoeverIsNotTheOperatorCannotRestartAndTheGameGoesOn() throws Exception {
        WorldServer server = started(11);
        Client player = new Client(server, Role.AGENT, null);
        player.register("Guppy");
        player.play("Guppy", 5);
        assertThat(player.next(PerceptionMessage.class).tick()).isEqualTo(5);

        CompletableFuture<Reply> asked = player.connection.request(seq -> new GameControlMessage(seq,
                GameCommand.RESTART, 3L));
        player.connection.send(seq -> new EndTurnMessage(seq, 5));
        Reply refused = asked.get(10, TimeUnit.SECONDS);

        assertThat(refused).isInstanceOfSatisfying(ErrorMessage.class,
                error -> assertThat(error.code()).isEqualTo(ErrorCode.FORBIDDEN));
        assertThat(player.next(TickMessage.class).tick()).isEqualTo(6);
        assertThat(server.seed()).isEqualTo(11);
        assertThat(server.phase()).isEqualTo(Phase.RUNNING);
    }

    @Test
    void aVersionOneClientHearsTheGameEndAndIsLetGoWhileVersionTwoClientsStay() throws Exception {
        WorldServer server = started(11);
        MessageCodec codec = new MessageCodec();
        try (Socket old = new Socket("127.0.0.1", server.port())) {
            old.setSoTimeout(10_000);
            old.getOutputStream().write(("{\"type\":\"Hello\",\"seq\":1,\"protocolVersion\":1,\"role\":\"viewer\","
                    + "\"client\":\"v1\"}\n").getBytes(StandardCharsets.UTF_8));
            BufferedReader in = new BufferedReader(new InputStreamReader(old.getInputStream(), StandardCharsets.UTF_8));
            assertThat(codec.decodeServer(in.readLine())).isInstanceOf(WelcomeMessage.class);
            Client operator = new Client(server, Role.VIEWER, OPERATOR);

            operator.request(restart(4L));

            List<ServerMessage> told = new ArrayList<>();
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                told.add(codec.decodeServer(line));
            }
            assertThat(told).as("what the version 1 client was told after its snapshot").last()
                    .isInstanceOfSatisfying(ErrorMessage.class,
                            error -> assertThat(error.code()).isEqualTo(ErrorCode.GAME_NOT_RUNNING));
            assertThat(told).anyMatch(GameOverMessage.class::isInstance).noneMatch(NewGameMessage.class::isInstance);
            operator.next(NewGameMessage.class);
            assertThat(operator.connection.isOpen()).isTrue();
        }
    }

    @Test
    void aServerThatRecordsItsGameRefusesToRestartSayingWhy() throws Exception {
        WorldServer server = WorldServer.builder().port(0).seed(11).clock(ClockMode.LOCKSTEP)
                .record(dir.resolve("game.ndjson")).operatorToken(OPERATOR).start();
        open.add(server);
        Client operator = new Client(server, Role.VIEWER, OPERATOR);

        Reply refused = operator.request(restart(4L));

        assertThat(refused).isInstanceOfSatisfying(ActionResultMessage.class, result -> {
            assertThat(result.outcome()).isEqualTo(Outcome.REJECTED);
            assertThat(result.reason()).isEqualTo("this server plays one game: it records it; start a server for "
                    + "each game instead");
        });
        assertThatThrownBy(() -> server.restart(4)).isInstanceOf(IllegalStateException.class)
                .hasMessageContaining("records it");
        assertThat(server.seed()).isEqualTo(11);
    }

    @Test
    void theEmbeddingProgramRestartsTheGameAndWaitsForTheNewOnesEnd() throws Exception {
        WorldServer server = WorldServer.builder().port(0).seed(8).clock(ClockMode.REALTIME).timeLimit(0.2)
                .tickRate(50).start();
        open.add(server);
        server.startGame();
        CompletableFuture<List<Score>> first = server.gameOver();
        first.get(10, TimeUnit.SECONDS);

        server.restart(9);
        server.startGame();

        assertThat(server.gameOver()).isNotSameAs(first);
        server.gameOver().get(10, TimeUnit.SECONDS);
        assertThat(server.seed()).isEqualTo(9);
    }
}
