package io.orchard.cluster.game;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.EndTurnMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.InstructionMessage;
import io.orchard.protocol.message.MoveMessage;
import io.orchard.protocol.message.RegisteredMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.UnregisterMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.FileRecorder;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.Placement;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Everything that happens to a game under way, played by the single server's simulation and by a game
 * whose world is cut into parcels of 25 units, by the same script: an agent that registers after the
 * start, a viewer that connects late, an agent whose connection drops, a stranger refused its name,
 * its controller back with its resume token, an agent that unregisters, instructions, refused
 * messages, a restart refused, a pause with a registration and a viewer during it, turns missed,
 * and the end. Both games record the same file, byte for byte, and every client hears the same
 * messages in the same order, the late viewers' catching up included.
 */
class GameUnderWayTest {

    private static final Placement ANYWHERE = (name, radius) -> null;

    @TempDir
    Path dir;

    @Test
    void agentsAndViewersThatComeAndGoPausesAndMissedTurnsAreAsOnOneServer() throws Exception {
        SimulationConfig config = Games.lockstep(2, 6);
        Path single = dir.resolve("single.ndjson");
        Script onOne = new Script();
        try (FileRecorder recorder = FileRecorder.open(single)) {
            Simulation simulation = new Simulation(Games.world(), config, Games.SEED, "test", recorder, List.of(),
                    ANYWHERE);
            onOne.play(Games.of(simulation));
            simulation.stopped();
        }
        Script onParcels = new Script();
        try (FileRecorder recorder = FileRecorder.open(dir.resolve("split.ndjson"))) {
            World world = Games.world();
            SplitGame split = new SplitGame(world, config, Games.SEED, "test", recorder, List.of(), 25, ANYWHERE,
                    grid -> new LocalParcels(grid, world, config));
            onParcels.play(Games.of(split));
            assertThat(split.counts().handOvers()).as("agents walked from parcel to parcel").isPositive();
        }

        Games.sameRecordings(dir, single);
        onOne.heard().forEach((client, messages) -> {
            List<ServerMessage> got = onParcels.heard().get(client);
            for (int i = 0; i < Math.min(messages.size(), got.size()); i++) {
                assertThat(withoutToken(got.get(i))).as("message %d that %s heard", i, client)
                        .isEqualTo(withoutToken(messages.get(i)));
            }
            assertThat(got).as("what %s heard", client).hasSameSizeAs(messages);
        });
        String recording = Files.readString(single);
        assertThat(recording).as("the script's events are in the game")
                .contains("\"agent\":\"Late\",", "\"reason\":\"connection closed\"", "\"code\":\"name_in_use\"",
                        "\"reason\":\"unregistered\"", "\"turn\":\"deadline\"", "\"turn\":\"late\"",
                        "\"type\":\"Instruction\"", "\"code\":\"unknown_agent\"", "\"code\":\"wrong_role\"",
                        "\"code\":\"not_your_agent\"", "the game has already started", "the game is not running", "this server plays one game only",
                        "\"type\":\"ScoreUpdate\"", "\"type\":\"GameOver\"", "\"agent\":\"Extra\",");
        List<ServerMessage> lateViewer = onParcels.heard().get("viewer");
        assertThat(lateViewer.get(0)).as("the late viewer's first message").isInstanceOf(WorldSnapshotMessage.class);
        assertThat(((WorldSnapshotMessage) lateViewer.get(0)).tick()).as("the tick it caught up at").isEqualTo(20);
    }

    /** A message with its resume token left out: each game draws its own. */
    private static ServerMessage withoutToken(ServerMessage message) {
        return message instanceof RegisteredMessage r ? new RegisteredMessage(r.seq(), r.agent(), r.body(),
                r.position(), r.heading(), null, r.seed()) : message;
    }

    /** The script, the same for both games: who comes, goes and does what, tick by tick. */
    private static final class Script {

        private final TestSession first = new TestSession(1, Role.AGENT);
        private final TestSession second = new TestSession(2, Role.AGENT);
        private final TestSession late = new TestSession(3, Role.AGENT);
        private final TestSession viewer = new TestSession(10, Role.VIEWER);
        private final TestSession stranger = new TestSession(11, Role.AGENT);
        private final TestSession back = new TestSession(12, Role.AGENT);
        private final TestSession extra = new TestSession(13, Role.AGENT);
        private final TestSession pausedViewer = new TestSession(14, Role.VIEWER);
        private final Forager a = new Forager("ForagerA", first, 40);
        private final Forager b = new Forager("ForagerB", second, 30);
        private final Forager lateComer = new Forager("Late", late, 30);
        private final Forager bAgain = new Forager("ForagerB", back, 30);
        private final Forager extraOne = new Forager("Extra", extra, 20);
        private final List<Forager> playing = new ArrayList<>();
        private long seq = 1000;

        /** What each client heard, by a name of the script's. */
        Map<String, List<ServerMessage>> heard() {
            Map<String, List<ServerMessage>> heard = new LinkedHashMap<>();
            heard.put("first", first.all());
            heard.put("second", second.all());
            heard.put("late", late.all());
            heard.put("viewer", viewer.all());
            heard.put("stranger", stranger.all());
            heard.put("back", back.all());
            heard.put("extra", extra.all());
            heard.put("pausedViewer", pausedViewer.all());
            return heard;
        }

        void play(Games.Game game) {
            game.connected(first);
            game.connected(second);
            game.applyNow();
            a.register().forEach(m -> game.received(first, m));
            b.register().forEach(m -> game.received(second, m));
            game.applyNow();
            a.setUp().forEach(m -> game.received(first, m));
            b.setUp().forEach(m -> game.received(second, m));
            game.applyNow();
            assertThat(game.phase()).as("the game started").isEqualTo(Phase.RUNNING);
            playing.add(a);
            playing.add(b);
            while (game.phase() != Phase.OVER) {
                if (game.phase() == Phase.PAUSED) {
                    whilePaused(game);
                    continue;
                }
                game.beginTick();
                long tick = game.tick();
                during(tick, game);
                for (Forager agent : new ArrayList<>(playing)) {
                    for (ClientMessage message : agent.act(tick)) {
                        boolean skipped = agent == bAgain && tick >= 70 && tick < 76 && message instanceof EndTurnMessage;
                        if (!skipped) {
                            game.received(agent.session(), message);
                        }
                    }
                }
                if (tick == 50) {
                    game.received(first, new GameControlMessage(++seq, GameCommand.PAUSE));
                }
                game.endTick();
            }
        }

        /** What happens during the tick {@code tick}, besides the agents' own doings. */
        private void during(long tick, Games.Game game) {
            if (tick == 5) {
                game.received(first, new GameControlMessage(++seq, GameCommand.START));
                game.received(first, new GameControlMessage(++seq, GameCommand.RESTART, null));
            } else if (tick == 10) {
                game.connected(late);
                lateComer.register().forEach(m -> game.received(late, m));
            } else if (tick == 11) {
                lateComer.setUpIn(tick).forEach(m -> game.received(late, m));
                playing.add(lateComer);
            } else if (tick == 20) {
                game.connected(viewer);
            } else if (tick == 25) {
                game.received(viewer, new InstructionMessage(++seq, "ForagerA", "go north", "teacher"));
                game.received(viewer, new InstructionMessage(++seq, "Nobody", "hello", "teacher"));
                game.received(viewer, new MoveMessage(++seq, "ForagerA", null, Vec3.ground(0, 0)));
                game.received(first, new MoveMessage(++seq, "ForagerB", null, Vec3.ground(0, 0)));
            } else if (tick == 30) {
                game.disconnected(second, "connection closed");
                playing.remove(b);
            } else if (tick == 31) {
                game.connected(stranger);
                new Forager("ForagerB", stranger, 20).register().forEach(m -> game.received(stranger, m));
            } else if (tick == 33) {
                game.connected(back);
                bAgain.resume(token(second, "ForagerB")).forEach(m -> game.received(back, m));
            } else if (tick == 34) {
                bAgain.setUpIn(tick).forEach(m -> game.received(back, m));
                playing.add(bAgain);
            } else if (tick == 45) {
                game.received(late, new UnregisterMessage(++seq, "Late"));
                playing.remove(lateComer);
            }
        }

        /** While the game is paused: a newcomer, a viewer, a move refused, and the game goes on. */
        private void whilePaused(Games.Game game) {
            game.connected(extra);
            extraOne.register().forEach(m -> game.received(extra, m));
            game.applyNow();
            extraOne.setUpIn(game.tick()).forEach(m -> game.received(extra, m));
            game.applyNow();
            game.connected(pausedViewer);
            game.applyNow();
            game.received(first, new MoveMessage(++seq, "ForagerA", null, Vec3.ground(1, 1)));
            game.received(first, new GameControlMessage(++seq, GameCommand.RESUME));
            game.applyNow();
            playing.add(extraOne);
        }

        private static String token(TestSession session, String agent) {
            return session.all().stream().filter(m -> m instanceof RegisteredMessage r && r.agent().equals(agent))
                    .map(m -> ((RegisteredMessage) m).resumeToken()).findFirst().orElseThrow();
        }
    }
}
