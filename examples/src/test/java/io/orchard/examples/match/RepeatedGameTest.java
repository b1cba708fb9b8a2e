package io.orchard.examples.match;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Species;
import io.orchard.examples.Orchard;
import io.orchard.protocol.client.ProtocolConnection;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Role;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.Phase;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfSystemProperty;
import org.junit.jupiter.api.io.TempDir;

/**
 * The same lockstep game, played three times by the paper's five agents against a real server,
 * each agent on its own connection through a relay that delays every chunk of bytes at random, the
 * agents started in a different order and at different moments each time (and a viewer watching
 * one of the games from its middle): the three recordings are the same file, byte for byte.
 */
class RepeatedGameTest {

    private static final long SEED = 8;

    @TempDir
    Path dir;

    /** Plays one game of {@code seconds} and returns its recording. */
    private Path play(int run, List<Species> order, double seconds, boolean watched) throws Exception {
        Path recording = dir.resolve("game-" + run + ".ndjson");
        Random timing = new Random(run * 1000L + 17);
        List<AgentController> agents = order.stream().map(Species::create).toList();
        CountDownLatch done = new CountDownLatch(agents.size());
        List<Throwable> failures = Collections.synchronizedList(new ArrayList<>());
        try (WorldServer server = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP)
                .timeLimit(seconds).waitFor(agents.size()).lockstepDeadline(Duration.ofSeconds(20))
                .record(recording).start();
             DelayingRelay relay = new DelayingRelay(server.port(), run, 4)) {
            for (AgentController agent : agents) {
                Thread.sleep(timing.nextInt(150));
                Thread thread = new Thread(() -> {
                    try {
                        agent.run("127.0.0.1", relay.port());
                    } catch (Exception e) {
                        failures.add(e);
                    } finally {
                        done.countDown();
                    }
                }, "agent-" + agent.name());
                thread.setDaemon(true);
                thread.start();
            }
            if (watched) {
                while (server.phase() == Phase.WAITING) {
                    Thread.sleep(50);
                }
                Thread.sleep(500);
                try (ProtocolConnection viewer = ProtocolConnection.connect("127.0.0.1", relay.port(), Role.VIEWER,
                        "watching", message -> { })) {
                    server.gameOver().get(5, TimeUnit.MINUTES);
                }
            }
            server.gameOver().get(5, TimeUnit.MINUTES);
            assertThat(done.await(30, TimeUnit.SECONDS)).as("the agents finished").isTrue();
            assertThat(failures).isEmpty();
        }
        return recording;
    }

    private void threeGamesGiveOneRecording(double seconds) throws Exception {
        List<Species> named = Arrays.asList(Species.values());
        List<Species> reversed = new ArrayList<>(named);
        Collections.reverse(reversed);
        List<Species> shuffled = new ArrayList<>(named);
        Collections.shuffle(shuffled, new Random(3));

        long started = System.nanoTime();
        byte[] first = Files.readAllBytes(play(0, named, seconds, false));
        byte[] second = Files.readAllBytes(play(1, reversed, seconds, true));
        byte[] third = Files.readAllBytes(play(2, shuffled, seconds, false));
        System.out.printf("%d games of %.0f simulated seconds, recordings of %d bytes, in %.1f s%n", 3, seconds,
                first.length, (System.nanoTime() - started) / 1e9);

        String text = new String(first, StandardCharsets.UTF_8);
        assertThat(text).as("no turn was missed").doesNotContain("\"dir\":\"missed\"")
                .contains("\"type\":\"GameOver\"", "\"type\":\"FruitEaten\"");
        assertThat(second).as("the second recording, byte for byte").isEqualTo(first);
        assertThat(third).as("the third recording, byte for byte").isEqualTo(first);
    }

    @Test
    void theFiveAgentsPlayTheSameGameWhateverOrderAndTimingTheyConnectIn() throws Exception {
        threeGamesGiveOneRecording(20);
    }

    @Test
    void theFiveAgentsPlayTheSameGameInOneJvmAndEachInAJvmOfItsOwn() throws Exception {
        double seconds = 10;
        byte[] together = Files.readAllBytes(play(3, Arrays.asList(Species.values()), seconds, false));
        byte[] apart = Files.readAllBytes(playInProcesses(4, seconds));

        assertThat(new String(together, StandardCharsets.UTF_8)).as("no turn was missed")
                .doesNotContain("\"dir\":\"missed\"").contains("\"type\":\"GameOver\"");
        assertThat(apart).as("the recording of the agents in five JVMs, byte for byte").isEqualTo(together);
    }

    /** Plays one game of {@code seconds} with each agent run by {@code orchard agent} in a JVM of its own. */
    private Path playInProcesses(int run, double seconds) throws Exception {
        Path recording = dir.resolve("game-" + run + ".ndjson");
        List<Process> processes = new ArrayList<>();
        try (WorldServer server = WorldServer.builder().port(0).seed(SEED).clock(ClockMode.LOCKSTEP)
                .timeLimit(seconds).waitFor(Species.values().length).lockstepDeadline(Duration.ofSeconds(20))
                .record(recording).start()) {
            for (Species species : Species.values()) {
                List<String> command = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                        "-cp", System.getProperty("java.class.path"), Orchard.class.getName(), "agent",
                        "--type", species.name(), "--port", String.valueOf(server.port()));
                processes.add(new ProcessBuilder(command).redirectErrorStream(true)
                        .redirectOutput(dir.resolve(species.name() + "-" + run + ".log").toFile()).start());
            }
            try {
                server.gameOver().get(5, TimeUnit.MINUTES);
            } catch (java.util.concurrent.TimeoutException e) {
                StringBuilder logs = new StringBuilder();
                for (Species species : Species.values()) {
                    logs.append(species).append(":\n")
                            .append(Files.readString(dir.resolve(species.name() + "-" + run + ".log")));
                }
                throw new AssertionError("the game did not end within 5 minutes; the agents said:\n" + logs, e);
            }
            for (Process process : processes) {
                assertThat(process.waitFor(60, TimeUnit.SECONDS)).as("the agent's JVM exits after the game").isTrue();
                assertThat(process.exitValue()).as("its exit status").isZero();
            }
        } finally {
            processes.forEach(Process::destroyForcibly);
        }
        return recording;
    }

    /** The whole length of a game: {@code -Dorchard.full=true} (a few minutes). */
    @Test
    @EnabledIfSystemProperty(named = "orchard.full", matches = "true")
    void theFiveAgentsPlayTheSameWholeGameWhateverOrderAndTimingTheyConnectIn() throws Exception {
        threeGamesGiveOneRecording(300);
    }
}
