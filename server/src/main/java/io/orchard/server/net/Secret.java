package io.orchard.server.net;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;

/**
 * A secret a client must present, compared in constant time: the server keeps its SHA-256 digest
 * and compares the digest of what is offered with {@link MessageDigest#isEqual}, so that neither
 * where the bytes differ nor how long the secret is shows in the time an answer takes.
 */
final class Secret {

    private final byte[] digest;

    private Secret(byte[] digest) {
        this.digest = digest;
    }

    /** The secret {@code text}, or null when there is none. */
    static Secret of(String text) {
        return text == null ? null : new Secret(sha256(text));
    }

    /** Whether {@code offered} is this secret; null never is. */
    boolean matches(String offered) {
        return offered != null && MessageDigest.isEqual(digest, sha256(offered));
    }

    private static byte[] sha256(String text) {
        try {
            return MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }

    @Override
    public String toString() {
        return "Secret[hidden]";
    }
}
