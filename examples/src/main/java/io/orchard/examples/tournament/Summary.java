package io.orchard.examples.tournament;

import java.io.PrintStream;
import java.util.List;
import java.util.Locale;

/**
 * One agent's results over a tournament: the mean, spread and range of its fruit per game, and its
 * mean points.
 *
 * @param agent      the agent's name
 * @param games      the games it played
 * @param meanFruit  fruit per game, mean
 * @param sdFruit    fruit per game, sample standard deviation (0 for one game)
 * @param minFruit   fruit in its worst game
 * @param maxFruit   fruit in its best game
 * @param meanPoints points per game, mean
 */
record Summary(String agent, int games, double meanFruit, double sdFruit, int minFruit, int maxFruit,
               double meanPoints) {

    /** The summary of one agent's rows. */
    static Summary of(String agent, List<Result> results) {
        List<Result> mine = results.stream().filter(r -> r.agent().equals(agent)).toList();
        int n = mine.size();
        double mean = mine.stream().mapToInt(Result::fruit).average().orElse(0);
        double squares = mine.stream().mapToDouble(r -> (r.fruit() - mean) * (r.fruit() - mean)).sum();
        return new Summary(agent, n, mean, n > 1 ? Math.sqrt(squares / (n - 1)) : 0,
                mine.stream().mapToInt(Result::fruit).min().orElse(0),
                mine.stream().mapToInt(Result::fruit).max().orElse(0),
                mine.stream().mapToInt(Result::points).average().orElse(0));
    }

    /** Prints the table of means, one agent a line, in the order given. */
    static void printTable(List<Summary> summaries, PrintStream out) {
        out.println("agent          games  fruit mean     sd  min  max  points mean");
        for (Summary s : summaries) {
            out.printf(Locale.ROOT, "%-14s %5d  %10.2f %6.2f %4d %4d  %11.2f%n", s.agent(), s.games(), s.meanFruit(),
                    s.sdFruit(), s.minFruit(), s.maxFruit(), s.meanPoints());
        }
        out.flush();
    }
}
