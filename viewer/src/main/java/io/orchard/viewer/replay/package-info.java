/**
 * Recordings: reading the newline-delimited JSON a server writes with {@code --record}, and keeping
 * what a viewer needs to replay the game: the first world snapshot, the agents present then, and
 * every later message sent to all clients or to viewers, each with its simulated time.
 */
package io.orchard.viewer.replay;
