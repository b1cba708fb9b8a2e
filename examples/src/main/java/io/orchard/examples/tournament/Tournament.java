package io.orchard.examples.tournament;

import io.orchard.agents.AgentController;
import io.orchard.examples.match.Lineup;
import io.orchard.examples.match.Team;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Score;
import io.orchard.server.WorldServer;
import io.orchard.server.sim.GameListener;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Function;
import java.util.stream.Collectors;

/**
 * Plays the games of a tournament one after another, each on its own embedded server in lockstep
 * (a tick ends when every agent has ended its turn, so a game runs as fast as the agents decide and
 * a slow machine plays the same game), with new agents on threads of this JVM.
 *
 * @param games     how many games, each on its own seed
 * @param lineup    the agents that play every game
 * @param seedFrom  the seed of the first game; game i (from 1) has seed {@code seedFrom + i - 1}
 * @param timeLimit the length of each game in simulated seconds (a game ends sooner when all fruit is collected)
 * @param out       the folder of results.csv, results.json and chart.png
 */
record Tournament(int games, Lineup lineup, long seedFrom, double timeLimit, Path out) {

    /** How long one game may take on the wall clock before the tournament gives up. */
    private static final long GAME_LIMIT_MINUTES = 15;

    /** Plays every game and returns one row per agent per game, in game order and the line-up's order. */
    List<Result> play(ProgressBar progress) throws IOException, InterruptedException {
        List<Result> results = new ArrayList<>();
        for (int game = 1; game <= games; game++) {
            List<Result> rows = playOne(game, seedFrom + game - 1, progress);
            results.addAll(rows);
            progress.finished(game, String.format(Locale.ROOT, "game %d/%d (seed %d): %s", game, games,
                    seedFrom + game - 1, rows.stream().map(r -> r.agent() + " " + r.fruit())
                            .collect(Collectors.joining(", ")) + " fruit"));
        }
        return results;
    }

    private List<Result> playOne(int game, long seed, ProgressBar progress) throws IOException, InterruptedException {
        GameListener clock = new GameListener() {
            @Override
            public void tickEnded(long tick, double time) {
                progress.during(game, time / timeLimit, String.format(Locale.ROOT, "game %d/%d (seed %d) t=%.0f s",
                        game, games, seed, time));
            }
        };
        List<AgentController> agents = lineup.create();
        try (WorldServer server = WorldServer.builder().port(0).seed(seed).clock(ClockMode.LOCKSTEP)
                .timeLimit(timeLimit).waitFor(agents.size()).listener(clock).start();
             Team team = Team.play(agents, "127.0.0.1", server.port())) {
            List<Score> ranking;
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
            Map<String, Score> byAgent = ranking.stream().collect(Collectors.toMap(Score::agent, Function.identity()));
            List<Result> rows = new ArrayList<>();
            for (String name : lineup.names()) {
                Score score = byAgent.get(name);
                rows.add(new Result(game, seed, name, score == null ? 0 : score.fruit(),
                        score == null ? 0 : score.points()));
            }
            return rows;
        }
    }

    private static String failures(Team team) {
        return team.failures().isEmpty() ? "" : ": " + String.join("; ", team.failures());
    }
}
