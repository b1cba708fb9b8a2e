package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.server.world.scenario.ScenarioFile;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ServerMainTest {

    @TempDir
    Path dir;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String console, String... args) throws Exception {
        InputStream in = new ByteArrayInputStream(console.getBytes(StandardCharsets.UTF_8));
        return ServerMain.run(List.of(args), in, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    private String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    @Test
    void helpListsEveryOptionAndTheConsoleCommands() throws Exception {
        assertThat(run("", "--help")).isZero();
        // picocli wraps the footer at 80 columns
        assertThat(out().replaceAll("\\s+", " ")).contains("--port", "--bind", "--seed", "--clock", "--wait-for",
                "--scenario", "--time-limit",
                "--record", "--token", "--operator-token", "--checkpoint", "--checkpoint-every", "--resume",
                "--name-reservation", "--keep-serving", "--stop-on-stdin-close",
                "Console commands: start, pause, continue, status, checkpoint [FILE], restart [SEED], stop",
                "ORCHARD_OPERATOR_TOKEN");
    }

    @Test
    void withKeepServingTheConsoleRestartsTheGameAndTheServerServesTheNextUntilStopped() throws Exception {
        assertThat(run("restart 4\nstatus\nstop\n", "--port", "0", "--seed", "3", "--keep-serving", "--quiet"))
                .isZero();
        assertThat(out()).contains("restarting: a new game of seed 4 waits for its agents", "waiting  t=0.0s  tick 0");
        assertThat(out().split("Game over. Ranking:", -1)).as("games over: the restarted one, the stopped one")
                .hasSize(3);
    }

    @Test
    void withoutKeepServingTheServerPlaysOneGameAndARestartIsRefusedSayingHow() throws Exception {
        assertThat(run("restart 4\n", "--port", "0", "--seed", "3", "--quiet", "--stop-on-stdin-close")).isZero();
        assertThat(out()).contains("cannot restart: this server stops when its game is over: start it with "
                + "--keep-serving to restart games");
        assertThat(out().split("Game over. Ranking:", -1)).hasSize(2);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
        unknown option   | --colour=blue      | unknown option: '--colour=blue'
        port too large   | --port=70000       | invalid value for option '--port': '70000' is out of range (expected a port 0-65535)
        clock misspelled | --clock=lockstop   | invalid value for option '--clock': 'lockstop' is not a clock (expected one of realtime, lockstep)
        seed not number  | --seed=abc         | invalid value for option '--seed': 'abc' is not an integer
        negative every   | --checkpoint-every=-1 | invalid value for option '--checkpoint-every': '-1' is out of range
        negative keeping | --name-reservation=-5 | invalid value for option '--name-reservation': '-5' is out of range (expected 0-10000000 seconds; 0 frees a dropped agent's name at once)
        port given twice | --port=1 --port=2  | option '--port' (N) should be specified only once
        no value         | --port             | missing required parameter for option '--port' (N)
        stray argument   | 7557               | unexpected argument '7557'
        """)
    void aBadOptionIsNamedAndExitsWithTwo(String name, String line, String message) throws Exception {
        assertThat(run("", line.split(" "))).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("orchard server: " + message);
    }

    @Test
    void aValueOfTheWrongTypeIsNamedWithTheOptionAndWhatWasExpected() throws Exception {
        assertThat(run("", "--port", "abc")).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).isEqualTo("""
                orchard server: invalid value for option '--port': 'abc' is not an integer (expected a port 0-65535)
                Run ./orchard server --help for its options.
                """.replace("\n", System.lineSeparator()));
        assertThat(out()).isEmpty();
    }

    @Test
    void writeScenarioWritesTheGeneratedWorldOfTheSeed() throws Exception {
        Path file = dir.resolve("world.json");
        assertThat(run("", "--seed", "5", "--write-scenario", file.toString())).isZero();
        assertThat(ScenarioFile.read(file)).isEqualTo(io.orchard.server.world.WorldGenerator.standard(5).scenario());
    }

    @Test
    void aConsoleStartRunsTheGameToItsTimeLimitAndPrintsTheRanking() throws Exception {
        Path record = dir.resolve("game.ndjson");
        assertThat(run("status\nstart\n", "--port", "0", "--seed", "3", "--time-limit", "0.5", "--tick-rate", "50",
                "--record", record.toString())).isZero();
        assertThat(out()).contains("listening on port", "seed 3", "Game over. Ranking:");
        assertThat(java.nio.file.Files.readString(record)).contains("\"type\":\"WorldSnapshot\"", "\"type\":\"GameStarted\"", "\"type\":\"GameOver\"");
    }

    @Test
    void theConsoleCheckpointCommandAndTheEndOfTheGameSaveItAndAResumedEndedGameJustReportsIt() throws Exception {
        Path checkpoint = dir.resolve("game.json");
        Path elsewhere = dir.resolve("elsewhere.json");
        assertThat(run("checkpoint\ncheckpoint " + elsewhere + "\nstart\n", "--port", "0", "--seed", "3",
                "--time-limit", "0.5", "--tick-rate", "50", "--checkpoint", checkpoint.toString(), "--quiet")).isZero();
        assertThat(out()).contains("checkpoint written to " + checkpoint, "checkpoint written to " + elsewhere);
        io.orchard.server.sim.Checkpoint saved = io.orchard.server.sim.CheckpointFile.read(checkpoint);
        assertThat(saved.seed()).isEqualTo(3);
        assertThat(saved.phase()).isEqualTo("over");
        assertThat(io.orchard.server.sim.CheckpointFile.read(elsewhere).seed()).isEqualTo(3);
        out.reset();
        assertThat(run("", "--port", "0", "--resume", checkpoint.toString(), "--quiet")).isZero();
        assertThat(out()).contains("resumed from", "over", "Game over. Ranking:");
    }

    @Test
    void whenTheConsoleInputEndsTheServerSaysSoOnceAndPlaysOn() throws Exception {
        Path record = dir.resolve("game.ndjson");
        assertThat(run("start\n", "--port", "0", "--seed", "3", "--time-limit", "0.5", "--tick-rate", "50",
                "--record", record.toString(), "--quiet")).isZero();
        assertThat(out().split("console input closed", -1)).as("times the closed input is told").hasSize(2);
        assertThat(out()).contains("console input closed: the server runs on without its console; stop it with "
                + "Ctrl-C or kill " + ProcessHandle.current().pid() + " (SIGTERM)", "Game over. Ranking:");
        assertThat(java.nio.file.Files.readString(record)).contains("\"reason\":\"time limit reached\"");
    }

    @Test
    void withStopOnStdinCloseTheEndOfTheConsoleInputEndsTheGameAndTheServer() throws Exception {
        Path record = dir.resolve("game.ndjson");
        assertThat(run("", "--port", "0", "--seed", "3", "--record", record.toString(), "--quiet",
                "--stop-on-stdin-close")).isZero();
        assertThat(out()).contains("console input closed: the game ends and the server stops "
                + "(--stop-on-stdin-close)", "Game over. Ranking:");
        assertThat(java.nio.file.Files.readString(record))
                .contains("\"reason\":\"the server's console input closed\"");
    }

    @Test
    void theConsolePausesAndContinuesTheGame() throws Exception {
        java.io.PipedOutputStream typed = new java.io.PipedOutputStream();
        java.io.PipedInputStream console = new java.io.PipedInputStream(typed);
        java.util.concurrent.CompletableFuture<Integer> exit = java.util.concurrent.CompletableFuture.supplyAsync(
                () -> ServerMain.run(List.of("--port", "0", "--seed", "3", "--time-limit", "2", "--tick-rate", "50",
                        "--quiet"), console, new PrintStream(out, true, StandardCharsets.UTF_8),
                        new PrintStream(err, true, StandardCharsets.UTF_8)));
        typed.write("start\npause\nstatus\n".getBytes(StandardCharsets.UTF_8));
        typed.flush();
        awaitStatusLines("paused  t=", 1);
        for (int asked = 2; asked <= 3; asked++) {
            Thread.sleep(300);
            typed.write("status\n".getBytes(StandardCharsets.UTF_8));
            typed.flush();
            awaitStatusLines("paused  t=", asked);
        }
        List<String> paused = out().lines().filter(line -> line.startsWith("paused  t=")).toList();
        assertThat(paused.get(2)).as("the game's time and tick while paused").isEqualTo(paused.get(1));
        typed.write("continue\n".getBytes(StandardCharsets.UTF_8));
        typed.close();
        assertThat(exit.get(30, java.util.concurrent.TimeUnit.SECONDS)).isZero();
        assertThat(out()).contains("Game over. Ranking:");
    }

    private void awaitStatusLines(String start, int count) throws InterruptedException {
        long end = System.nanoTime() + java.util.concurrent.TimeUnit.SECONDS.toNanos(10);
        while (out().lines().filter(line -> line.startsWith(start)).count() < count) {
            assertThat(System.nanoTime()).as("waiting for %d lines '%s...' in:%n%s", count, start, out())
                    .isLessThan(end);
            Thread.sleep(10);
        }
    }

    @Test
    void aCheckpointCommandWithoutAFileSaysHowToNameOne() throws Exception {
        assertThat(run("checkpoint\nstart\n", "--port", "0", "--seed", "3", "--time-limit", "0.3", "--tick-rate", "50",
                "--quiet")).isZero();
        assertThat(out()).contains("has no checkpoint file", "(checkpoint FILE)");
    }

    @Test
    void aTakenPortIsNamedWithWhatToDoAndExitsWithOne() throws Exception {
        try (WorldServer other = WorldServer.builder().port(0).seed(1).start()) {
            assertThat(run("", "--port", String.valueOf(other.port()))).isEqualTo(1);
        }
        assertThat(err.toString(StandardCharsets.UTF_8)).startsWith("orchard server: cannot listen on port ")
                .contains("address already in use (is another server running? choose another with --port)");
    }

    @Test
    void aMissingScenarioOrSavedGameIsNamedWithItsOptionAndExitsWithOne() throws Exception {
        Path missing = dir.resolve("nonexistent.json");
        assertThat(run("", "--port", "0", "--scenario", missing.toString())).isEqualTo(1);
        assertThat(run("", "--port", "0", "--resume", missing.toString())).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8)).isEqualTo(String.join(System.lineSeparator(),
                "orchard server: cannot read the scenario file " + missing + " (--scenario): no such file",
                "orchard server: cannot read the checkpoint " + missing + " (--resume): no such file", ""));
    }

    @Test
    void anUnreadableCheckpointIsNamedAndExitsWithOne() throws Exception {
        Path bad = dir.resolve("bad.json");
        java.nio.file.Files.writeString(bad, "{\"format\":1}");
        assertThat(run("", "--port", "0", "--resume", bad.toString())).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("bad.json is not a checkpoint");
    }
}
