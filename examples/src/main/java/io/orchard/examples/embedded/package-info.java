/**
 * Embedding the world server in a JVM program: {@link io.orchard.examples.embedded.EmbeddedGame}
 * starts a server and two agents in one JVM and listens to the game's events.
 */
package io.orchard.examples.embedded;
