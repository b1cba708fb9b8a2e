package io.orchard.agents.cli;

import io.orchard.cli.Port;
import picocli.CommandLine.Option;

/** The options that say which server to play on, shared by {@code agent} and {@code agents}. */
final class ServerAddress {

    @Option(names = "--host", paramLabel = "HOST", defaultValue = "localhost",
            description = "The server's host (default: ${DEFAULT-VALUE})")
    String host;

    @Option(names = "--port", paramLabel = "N", defaultValue = "7557", converter = Port.class,
            description = "The server's port (default: ${DEFAULT-VALUE})")
    int port;

    @Option(names = "--token", paramLabel = "SECRET", description = "The token the server requires, if any")
    String token;
}
