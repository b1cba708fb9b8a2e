/**
 * The agents' command lines: {@code ./orchard agent} runs one agent of the zoo,
 * {@code ./orchard agents} runs all five, each on its own connection; lines typed on the console
 * are instructions, and what the agents say is printed.
 */
package io.orchard.agents.cli;
