package io.orchard.examples.tournament;

/**
 * One agent's result in one game of a tournament: a row of results.csv and results.json.
 *
 * @param game   the game's number, from 1
 * @param seed   the seed of its world
 * @param agent  the agent's name
 * @param fruit  the fruit it collected
 * @param points the points it scored
 */
record Result(int game, long seed, String agent, int fruit, int points) {}
