package io.orchard.cluster;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.server.WorldServer;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import org.assertj.core.api.ThrowableAssert.ThrowingCallable;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A node's builder refuses the options it shares with a server's as the server's does, in the same
 * words, before anything starts: a node is configured like one server.
 */
class ClusterNodeBuilderTest {

    @Test
    void aBadTickRateIsRefusedAsByAServer() {
        refusedAlike(() -> ClusterNode.builder().tickRate(0), () -> WorldServer.builder().tickRate(0),
                "tick rate must be 1 to 1000 ticks per second, was 0");
        refusedAlike(() -> ClusterNode.builder().tickRate(1001), () -> WorldServer.builder().tickRate(1001),
                "tick rate must be 1 to 1000 ticks per second, was 1001");
    }

    @Test
    void theGamesLengthWaitAndDeadlineAreRefusedAsByAServer() {
        refusedAlike(() -> ClusterNode.builder().timeLimit(Double.POSITIVE_INFINITY),
                () -> WorldServer.builder().timeLimit(Double.POSITIVE_INFINITY),
                "time limit must be a positive number of seconds, was Infinity");
        refusedAlike(() -> ClusterNode.builder().waitFor(-1), () -> WorldServer.builder().waitFor(-1),
                "waitFor must not be negative, was -1");
        refusedAlike(() -> ClusterNode.builder().lockstepDeadline(Duration.ZERO),
                () -> WorldServer.builder().lockstepDeadline(Duration.ZERO),
                "lockstep deadline must be positive, was PT0S");
        refusedAlike(() -> ClusterNode.builder().nameReservation(Duration.ofSeconds(-1)),
                () -> WorldServer.builder().nameReservation(Duration.ofSeconds(-1)),
                "name reservation must be zero or more, was PT-1S");
        refusedAlike(() -> ClusterNode.builder().checkpoint(Path.of("game.json"), Duration.ZERO),
                () -> WorldServer.builder().checkpoint(Path.of("game.json"), Duration.ZERO),
                "checkpoint interval must be positive, was PT0S");
    }

    @Test
    void portsAreRefusedAsByAServerEachByItsName() {
        refusedAlike(() -> ClusterNode.builder().port(65536), () -> WorldServer.builder().port(65536),
                "port must be 0 to 65535, was 65536");
        assertThatThrownBy(() -> ClusterNode.builder().clusterPort(-1)).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("cluster port must be 0 to 65535, was -1");
    }

    @Test
    void theTokensAreRefusedAsByAServerWhicheverIsGivenFirst() {
        refusedAlike(() -> ClusterNode.builder().token(""), () -> WorldServer.builder().token(""),
                "token must not be empty");
        refusedAlike(() -> ClusterNode.builder().operatorToken(""), () -> WorldServer.builder().operatorToken(""),
                "operator token must not be empty");
        String same = "the operator token must differ from the token: every client holds the token, and would "
                + "control the game";
        refusedAlike(() -> ClusterNode.builder().token("s").operatorToken("s"),
                () -> WorldServer.builder().token("s").operatorToken("s"), same);
        refusedAlike(() -> ClusterNode.builder().operatorToken("s").token("s"),
                () -> WorldServer.builder().operatorToken("s").token("s"), same);
    }

    @Test
    void theNodesCommandLineRefusesTheSameTwoTokensAsABadCommandLine() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = NodeMain.command(new ByteArrayInputStream(new byte[0]),
                        new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8))
                .execute("--port", "0", "--cluster-port", "0", "--token", "s", "--operator-token", "s");
        assertThat(status).as("exit status; out: %s", out.toString(StandardCharsets.UTF_8)).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("the operator token must differ from the token");
    }

    @Test
    void aNodeWhoseScenarioCannotBeReadSaysWhichFileAndStartsNoCluster(@TempDir Path dir) {
        Path missing = dir.resolve("no-such-world.json");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = NodeMain.command(new ByteArrayInputStream(new byte[0]),
                        new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8))
                .execute("--port", "0", "--cluster-port", "0", "--scenario", missing.toString());
        assertThat(status).as("exit status; out: %s", out.toString(StandardCharsets.UTF_8)).isNotZero();
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("cannot read the scenario file " + missing
                + " (--scenario)");
        assertThat(out.toString(StandardCharsets.UTF_8)).doesNotContain("node listening");
    }

    private static void refusedAlike(ThrowingCallable node, ThrowingCallable server, String message) {
        assertThatThrownBy(server).as("the server's builder").isInstanceOf(IllegalArgumentException.class)
                .hasMessage(message);
        assertThatThrownBy(node).as("the node's builder").isInstanceOf(IllegalArgumentException.class)
                .hasMessage(message);
    }
}
