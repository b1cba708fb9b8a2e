package io.orchard.examples.firstagent;

import io.orchard.examples.OptionsCommand;
import io.orchard.examples.Orchard;
import io.orchard.examples.match.Ranking;
import io.orchard.protocol.cli.Options;
import io.orchard.protocol.cli.UsageException;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.value.Checks;
import java.io.IOException;
import java.net.ConnectException;
import java.io.PrintStream;
import java.util.List;

/**
 * {@code ./orchard first-agent [--host H] [--port N] [--name NAME]}: plays {@link FirstAgent}
 * against a running server and prints the ranking when the game is over. The launcher rebuilds
 * the project first when a source changed, so an edit of {@code FirstAgent.java} is played at once.
 */
public final class FirstAgentCommand extends OptionsCommand {

    private static final Options OPTIONS = new Options("orchard first-agent",
            "Plays the tutorial's FirstAgent (examples/src/main/java/io/orchard/examples/firstagent/FirstAgent.java)"
                    + "\nagainst a running Orchard server, and prints the ranking when the game is over"
                    + " (docs/tutorial.md).")
            .value("host", "HOST", "the server's host", "localhost")
            .value("port", "N", "the server's port", "7557")
            .value("name", "NAME", "the agent's name in the world", "FirstAgent")
            .value("token", "SECRET", "the token the server requires, if any", null);

    /** Runs {@code ./orchard first-agent} with these arguments. */
    public static void main(String[] args) {
        Orchard.runAndExit("first-agent", args);
    }

    /** The {@code ./orchard first-agent} command. */
    public FirstAgentCommand() {
        super("first-agent", "play the tutorial's FirstAgent against a running server", OPTIONS);
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws Exception {
        Options.Parsed options = OPTIONS.parse(args);
        String name = options.string("name");
        try {
            Checks.name(name, "--name");
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        String host = options.string("host");
        int port = options.integer("port", 1, 65535);
        out.println(name + " is connecting to " + host + ":" + port);
        out.flush();
        try {
            GameOverMessage over = new FirstAgent(name).run(host, port, options.string("token"));
            if (over != null) {
                Ranking.print(over.reason(), over.ranking(), out);
            }
            return 0;
        } catch (ConnectException e) {
            err.println("orchard first-agent: " + e.getMessage()
                    + "; start one first, for example with ./orchard server");
            return 1;
        } catch (IOException e) {
            err.println("orchard first-agent: " + e.getMessage());
            return 1;
        }
    }
}
