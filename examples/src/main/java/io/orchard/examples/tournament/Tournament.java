package io.orchard.examples.tournament;

import io.orchard.agents.AgentController;
import io.orchard.agents.AgentStats;
import io.orchard.examples.match.Lineup;
import io.orchard.examples.match.Team;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Score;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.GameListener;
import io.orchard.server.sim.MissedTurn;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Function;
import java.util.stream.Collectors;

/**
 * Plays the games of a tournament one after another, each on its own embedded server in lockstep
 * (a tick ends when every agent has ended its turn, so a game runs as fast as the agents decide and
 * a slow machine plays the same game), with new agents on threads of this JVM. A game in which no
 * turn was missed is the same every time its seed is played; the turns missed are reported.
 *
 * @param games        how many games, each on its own seed
 * @param lineup       the agents that play every game
 * @param seedFrom     the seed of the first game; game i (from 1) has seed {@code seedFrom + i - 1}
 * @param timeLimit    the length of each game in simulated seconds (a game ends sooner when all fruit is collected)
 * @param turnDeadline how long (wall clock) a tick waits for an agent's turn before it goes on without it
 * @param out          the folder of results.csv, results.json, results.md and chart.png
 */
record Tournament(int games, Lineup lineup, long seedFrom, double timeLimit, Duration turnDeadline, Path out) {

    /** How long one game may take on the wall clock before the tournament gives up. */
    private static final long GAME_LIMIT_MINUTES = 15;

    /** Plays every game, in order. */
    List<Played> play(ProgressBar progress) throws IOException, InterruptedException {
        List<Played> played = new ArrayList<>();
        for (int game = 1; game <= games; game++) {
            Played one = playOne(game, seedFrom + game - 1, progress);
            played.add(one);
            progress.finished(game, String.format(Locale.ROOT, "game %d/%d (seed %d): %s fruit%s", game, games,
                    one.seed(), one.rows().stream().map(r -> r.agent() + " " + r.fruit())
                            .collect(Collectors.joining(", ")), one.missed().isEmpty() ? ""
                            : "; missed turns: " + describe(one.missed())));
        }
        return played;
    }

    /** The turns missed, as a person reads them: "Robot at tick 12 (deadline), ...". */
    static String describe(List<MissedTurn> missed) {
        return missed.stream().map(m -> String.join("+", m.agents()) + " at tick " + m.tick() + " ("
                + m.kind().wireName() + ")").collect(Collectors.joining(", "));
    }

    private Played playOne(int game, long seed, ProgressBar progress) throws IOException, InterruptedException {
        List<MissedTurn> missed = new CopyOnWriteArrayList<>();
        int[] fruitAtStart = new int[1];
        double[] lastTime = new double[1];
        GameListener listener = new GameListener() {
            @Override
            public void gameStarted(long seed, int fruitCount, double limit) {
                fruitAtStart[0] = fruitCount;
            }

            @Override
            public void turnMissed(MissedTurn turn) {
                missed.add(turn);
            }

            @Override
            public void tickEnded(long tick, double time) {
                lastTime[0] = time;
                progress.during(game, time / timeLimit, String.format(Locale.ROOT, "game %d/%d (seed %d) t=%.0f s",
                        game, games, seed, time));
            }
        };
        List<AgentController> agents = lineup.create();
        List<Score> ranking;
        try (WorldServer server = WorldServer.builder().port(0).seed(seed).clock(ClockMode.LOCKSTEP)
                .timeLimit(timeLimit).waitFor(agents.size()).lockstepDeadline(turnDeadline).listener(listener).start();
             Team team = Team.play(agents, "127.0.0.1", server.port())) {
            try {
                ranking = server.gameOver().get(GAME_LIMIT_MINUTES, TimeUnit.MINUTES);
            } catch (ExecutionException | TimeoutException e) {
                throw new IOException("game " + game + " (seed " + seed + ") did not end within " + GAME_LIMIT_MINUTES
                        + " minutes" + failures(team), e);
            }
            team.await(10, TimeUnit.SECONDS);
            if (!team.failures().isEmpty()) {
                throw new IOException("game " + game + " (seed " + seed + "): agents could not play" + failures(team));
            }
        }
        // The server is closed, its thread stopped: what the listener heard is complete.
        Map<String, Score> byAgent = ranking.stream().collect(Collectors.toMap(Score::agent, Function.identity()));
        List<Result> rows = new ArrayList<>();
        for (String name : lineup.names()) {
            Score score = byAgent.get(name);
            rows.add(new Result(game, seed, name, score == null ? 0 : score.fruit(), score == null ? 0 : score.points()));
        }
        long moves = 0;
        long refused = 0;
        for (AgentController agent : agents) {
            AgentStats stats = agent.stats();
            moves += stats.movesSent();
            refused += stats.obstacleRejections();
        }
        return new Played(game, seed, fruitAtStart[0], lastTime[0], rows, moves, refused, missed);
    }

    private static String failures(Team team) {
        return team.failures().isEmpty() ? "" : ": " + String.join("; ", team.failures());
    }
}
