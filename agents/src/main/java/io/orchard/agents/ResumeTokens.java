package io.orchard.agents;

import io.orchard.protocol.value.Nullable;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One agent's resume token, kept in a {@link ResumeTokenFile} across runs of its controller: the
 * token the file holds for the agent is presented when it registers, the one the server gives is
 * written, and it is removed when the game is over, since it is of no use after. A file that
 * cannot be read or written costs only the agent's coming back: it is logged, and the agent plays.
 */
final class ResumeTokens {

    private static final Logger log = LoggerFactory.getLogger(ResumeTokens.class);

    private final ResumeTokenFile file;
    private final String agent;
    /** The token presented at registration, or that the server gave since. */
    private String held;

    ResumeTokens(ResumeTokenFile file, String agent) {
        this.file = Objects.requireNonNull(file, "resume token file");
        this.agent = agent;
    }

    /**
     * The token to register with: the file's for this agent, or null when it has none. What writers
     * killed before their rename left beside the file is deleted first: it holds tokens.
     */
    @Nullable String toPresent() {
        try {
            file.removeLeftovers();
            held = file.read().get(agent);
        } catch (IOException e) {
            log.warn("{}: cannot read the resume tokens in {}, registering without one: {}", agent, file.path(),
                    e.toString());
            held = null;
        }
        return held;
    }

    /** The server registered the agent with {@code token}: the file keeps it, unless it had it already. */
    void registered(@Nullable String token) {
        if (token == null || token.equals(held)) {
            return;
        }
        if (token.isBlank() || token.contains("\n") || token.contains("\r")) {
            log.warn("{}: the server's resume token is not one line of text; it is not kept", agent);
            return;
        }
        held = token;
        try {
            file.update(tokens -> tokens.put(agent, token));
        } catch (IOException e) {
            log.warn("{}: cannot keep the resume token in {}: {}", agent, file.path(), e.toString());
        }
    }

    /** The game is over: the file forgets the agent's token, unless another run wrote a newer one meanwhile. */
    void gameOver() {
        if (held == null) {
            return;
        }
        String done = held;
        try {
            file.update(tokens -> tokens.remove(agent, done));
        } catch (IOException e) {
            log.warn("{}: cannot remove the resume token of the game that is over from {}: {}", agent, file.path(),
                    e.toString());
        }
    }

    Path path() {
        return file.path();
    }
}
