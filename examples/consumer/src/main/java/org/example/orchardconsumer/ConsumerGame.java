package org.example.orchardconsumer;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Dwarf;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Score;
import io.orchard.server.WorldServer;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

/**
 * Embeds Orchard's world server on a free port, plays a short lockstep game of this program's
 * {@link Gatherer} against the zoo's Dwarf on threads of this JVM, and prints the ranking.
 * Arguments: the world's seed and the game's length in simulated seconds (1998 and 60 if absent).
 */
public final class ConsumerGame {

    private ConsumerGame() {}

    public static void main(String[] args) throws Exception {
        long seed = args.length > 0 ? Long.parseLong(args[0]) : 1998;
        double timeLimit = args.length > 1 ? Double.parseDouble(args[1]) : 60;
        List<AgentController> agents = List.of(new Gatherer(), new Dwarf());
        ExecutorService threads = Executors.newFixedThreadPool(agents.size());
        try (WorldServer server = WorldServer.builder().port(0).seed(seed).clock(ClockMode.LOCKSTEP)
                .timeLimit(timeLimit).waitFor(agents.size()).start()) {
            System.out.printf(Locale.ROOT, "world server on port %d, seed %d%n", server.port(), server.seed());
            for (AgentController agent : agents) {
                threads.submit(() -> agent.run("127.0.0.1", server.port()));
            }
            List<Score> ranking = server.gameOver().get(5, TimeUnit.MINUTES);
            System.out.println("Ranking:");
            for (int i = 0; i < ranking.size(); i++) {
                Score score = ranking.get(i);
                System.out.printf(Locale.ROOT, "%3d. %-10s %3d points %3d fruit%n",
                        i + 1, score.agent(), score.points(), score.fruit());
            }
        } finally {
            agents.forEach(AgentController::stop);
            threads.shutdown();
            threads.awaitTermination(10, TimeUnit.SECONDS);
        }
    }
}
