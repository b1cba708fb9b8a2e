/**
 * Tournaments: {@code ./orchard tournament} plays K games over K seeds with chosen agents in
 * lockstep, and writes the results as CSV, JSON and a box plot — how a teacher compares the
 * agents' control architectures.
 */
package io.orchard.examples.tournament;
