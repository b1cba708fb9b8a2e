package io.orchard.examples.embedded;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Dwarf;
import io.orchard.agents.zoo.Robot;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Score;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.GameListener;
import java.io.PrintStream;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

/**
 * The pattern for embedding Orchard in a JVM program: start a {@link WorldServer} in-process on a
 * free port with a seed, start two agents in the same JVM, hear the game's events through a
 * {@link GameListener} and print the ranking. Nothing here is private to Orchard: it uses the
 * public API only. Run it with {@code ./orchard embedded [--seed N] [--time-limit SECONDS]}, or
 * with this class as the main class and the seed as its argument.
 */
public final class EmbeddedGame {

    private EmbeddedGame() {}

    public static void main(String[] args) throws Exception {
        long seed = args.length > 0 ? Long.parseLong(args[0]) : 1998;
        play(seed, 60, System.out);
    }

    /**
     * Plays one game of Dwarf against Robot in lockstep (as fast as the agents decide) and prints
     * what happens, then the ranking.
     *
     * @param timeLimit the game's length in simulated seconds
     * @return the ranking, best first
     */
    public static List<Score> play(long seed, double timeLimit, PrintStream out) throws Exception {
        // Called on the server's simulation thread: print and return, never block there.
        GameListener events = new GameListener() {
            @Override
            public void gameStarted(long worldSeed, int fruitCount, double limit) {
                out.printf(Locale.ROOT, "game started: seed %d, %d fruit, %.0f s%n", worldSeed, fruitCount, limit);
            }

            @Override
            public void fruitEaten(String agent, String fruit, FruitKind kind, double time) {
                out.printf(Locale.ROOT, "%6.1f s  %s collected %s %s%n", time, agent, kind.name().toLowerCase(
                        Locale.ROOT), fruit);
            }

            @Override
            public void gameOver(String reason, List<Score> ranking) {
                out.println("game over: " + reason);
            }
        };
        List<AgentController> agents = List.of(new Dwarf(), new Robot());
        ExecutorService threads = Executors.newFixedThreadPool(agents.size());
        // Port 0: any free port. LOCKSTEP: a tick ends when both agents have ended their turn.
        try (WorldServer server = WorldServer.builder().port(0).seed(seed).clock(ClockMode.LOCKSTEP)
                .timeLimit(timeLimit).waitFor(agents.size()).listener(events).start()) {
            out.printf(Locale.ROOT, "world server on port %d, seed %d%n", server.port(), server.seed());
            for (AgentController agent : agents) {
                threads.submit(() -> agent.run("127.0.0.1", server.port()));
            }
            List<Score> ranking = server.gameOver().get(10, TimeUnit.MINUTES);
            out.println("Ranking:");
            int place = 1;
            for (Score score : ranking) {
                out.printf(Locale.ROOT, "%3d. %-10s %3d points %3d fruit%n", place++, score.agent(), score.points(),
                        score.fruit());
            }
            return ranking;
        } finally {
            agents.forEach(AgentController::stop);
            threads.shutdown();
            threads.awaitTermination(10, TimeUnit.SECONDS);
        }
    }
}
