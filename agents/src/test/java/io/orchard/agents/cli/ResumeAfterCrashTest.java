package io.orchard.agents.cli;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.TickMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Score;
import io.orchard.server.ServerMain;
import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.CheckpointFile;
import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A crash from start to finish, as an operator meets it: a server saving the game to a checkpoint
 * file, and the five agents of {@code ./orchard agents} keeping their resume tokens; the server
 * killed without warning (SIGKILL); the server started again with {@code --resume}, and the same
 * agents command run again. Every agent comes back, the game goes on from where it was saved, and
 * the scores are kept.
 */
class ResumeAfterCrashTest {

    private static final Pattern LISTENING = Pattern.compile("listening on port (\\d+)");
    private static final Set<String> FIVE = Set.of("Dwarf", "Robot", "Bunny", "Guppy", "Roadrunner");

    @TempDir
    Path dir;

    private final List<Process> servers = new ArrayList<>();

    @AfterEach
    void killServers() {
        servers.forEach(Process::destroyForcibly);
    }

    /** A server in a JVM of its own, and the port it listens on. */
    private record Server(Process process, int port) {
        void console(String line) throws IOException {
            OutputStream in = process.getOutputStream();
            in.write((line + "\n").getBytes(StandardCharsets.UTF_8));
            in.flush();
        }
    }

    private Server startServer(String... args) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> command = new ArrayList<>(List.of(java, "-cp", System.getProperty("java.class.path"),
                ServerMain.class.getName()));
        command.addAll(List.of(args));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        servers.add(process);
        CompletableFuture<Integer> port = new CompletableFuture<>();
        Thread output = new Thread(() -> {
            try (BufferedReader lines = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8))) {
                String line;
                while ((line = lines.readLine()) != null) {
                    Matcher matcher = LISTENING.matcher(line);
                    if (matcher.find()) {
                        port.complete(Integer.parseInt(matcher.group(1)));
                    }
                }
            } catch (IOException e) {
                // the server ended
            }
            port.completeExceptionally(new AssertionError("the server ended without listening"));
        }, "server-output");
        output.setDaemon(true);
        output.start();
        return new Server(process, port.get(120, TimeUnit.SECONDS));
    }

    /** {@code ./orchard agents} against {@code port}, in the background; it completes with its exit status. */
    private static CompletableFuture<Integer> agents(int port, Path tokens, ByteArrayOutputStream out,
                                                     ByteArrayOutputStream err) {
        PrintStream print = new PrintStream(out, true, StandardCharsets.UTF_8);
        PrintStream printErr = new PrintStream(err, true, StandardCharsets.UTF_8);
        return CompletableFuture.supplyAsync(() -> AgentMain.agents(List.of("--host", "127.0.0.1", "--port",
                String.valueOf(port), "--resume-tokens", tokens.toString()), InputStream.nullInputStream(), print,
                printErr));
    }

    private static Checkpoint readWhen(Path file, Predicate<Checkpoint> wanted, String what) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(180);
        while (true) {
            if (Files.exists(file)) {
                Checkpoint saved = CheckpointFile.read(file);
                if (wanted.test(saved)) {
                    return saved;
                }
            }
            assertThat(System.nanoTime()).as(what).isLessThan(deadline);
            Thread.sleep(100);
        }
    }

    private static Map<String, Integer> points(List<Score> scores) {
        return scores.stream().collect(Collectors.toMap(Score::agent, Score::points));
    }

    @Test
    void theSameAgentsCommandContinuesTheGameOfAServerThatWasKilled() throws Exception {
        Path checkpoint = dir.resolve("game.json");
        Path tokens = dir.resolve("resume-tokens");
        Server first = startServer("--port", "0", "--seed", "1998", "--clock", "lockstep", "--wait-for", "5",
                "--time-limit", "600", "--checkpoint", checkpoint.toString(), "--checkpoint-every", "0.5", "--quiet");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        CompletableFuture<Integer> firstRun = agents(first.port(), tokens, out, err);

        // Played until someone scored and the game was saved after it, with all five in it.
        Checkpoint saved = readWhen(checkpoint, c -> c.agents().size() == 5 && c.tick() > 40
                && c.scores().stream().anyMatch(s -> s.points() > 0), "a saved game in which someone scored");
        first.process().destroyForcibly().waitFor(30, TimeUnit.SECONDS);
        assertThat(firstRun.get(60, TimeUnit.SECONDS)).as(out.toString(StandardCharsets.UTF_8)).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("closed the connection");
        saved = CheckpointFile.read(checkpoint); // a later one may have been written before the kill
        assertThat(saved.agents()).extracting(Checkpoint.SavedAgent::name).containsExactlyInAnyOrderElementsOf(FIVE);
        assertThat(Files.readString(tokens)).contains(FIVE.toArray(String[]::new));

        Server again = startServer("--port", "0", "--resume", checkpoint.toString(), "--checkpoint",
                checkpoint.toString(), "--quiet");
        BlockingQueue<ServerMessage> seen = new LinkedBlockingQueue<>();
        List<String> back = new CopyOnWriteArrayList<>();
        try (ProtocolConnection viewer = ProtocolConnection.connect("127.0.0.1", again.port(), Role.VIEWER, "test",
                m -> {
                    if (m instanceof AgentAddedMessage added) {
                        back.add(added.agent().name());
                    }
                    seen.add(m);
                })) {
            WorldSnapshotMessage snapshot = (WorldSnapshotMessage) seen.poll(30, TimeUnit.SECONDS);
            assertThat(points(snapshot.scores())).isEqualTo(points(saved.scores()));
            assertThat(snapshot.tick()).isEqualTo(saved.tick());

            ByteArrayOutputStream outAgain = new ByteArrayOutputStream();
            ByteArrayOutputStream errAgain = new ByteArrayOutputStream();
            CompletableFuture<Integer> secondRun = agents(again.port(), tokens, outAgain, errAgain);
            // The game was paused until every agent was back; now the clock runs on from the saved tick.
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            long firstTick = -1;
            long lastTick = -1;
            while (lastTick < saved.tick() + 20) {
                ServerMessage message = seen.poll(1, TimeUnit.SECONDS);
                if (message instanceof TickMessage tick) {
                    firstTick = firstTick < 0 ? tick.tick() : firstTick;
                    lastTick = tick.tick();
                }
                assertThat(System.nanoTime()).as("ticks after the agents came back; agents said: %s %s",
                        outAgain.toString(StandardCharsets.UTF_8), errAgain.toString(StandardCharsets.UTF_8))
                        .isLessThan(deadline);
            }
            assertThat(firstTick).isEqualTo(saved.tick());
            assertThat(back).containsExactlyInAnyOrderElementsOf(FIVE);

            again.console("stop");
            assertThat(secondRun.get(60, TimeUnit.SECONDS)).as(errAgain.toString(StandardCharsets.UTF_8)).isZero();
            assertThat(errAgain.toString(StandardCharsets.UTF_8)).isEmpty();
            String report = outAgain.toString(StandardCharsets.UTF_8);
            assertThat(report).contains("Game over (stopped from the console). Ranking:");
            for (Score score : saved.scores()) {
                Matcher line = Pattern.compile(score.agent() + " +(\\d+) points").matcher(report);
                assertThat(line.find()).as("%s in the ranking", score.agent()).isTrue();
                assertThat(Integer.parseInt(line.group(1))).as("%s's points", score.agent())
                        .isGreaterThanOrEqualTo(score.points());
            }
        }
        // The game is over: its tokens are of no more use, and are gone.
        assertThat(Files.readString(tokens)).doesNotContain(FIVE.toArray(String[]::new));
    }
}
