package io.orchard.server.sim;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;

/**
 * An agent's own seed, from the game's seed and the agent's name: the first eight bytes, big-endian,
 * of the SHA-256 of the UTF-8 text {@code orchard-agent-seed:<game seed in decimal>:<name>}. Any
 * language can compute it; the same agent in a game of the same seed always gets the same one, and
 * two agents of one game draw differently.
 */
final class AgentSeed {

    private AgentSeed() {}

    static long of(long gameSeed, String name) {
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256")
                    .digest(("orchard-agent-seed:" + gameSeed + ":" + name).getBytes(StandardCharsets.UTF_8));
            return ByteBuffer.wrap(digest, 0, Long.BYTES).getLong();
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }
}
