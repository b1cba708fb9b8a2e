package io.orchard.examples.firstagent;

import io.orchard.cli.Port;
import io.orchard.examples.OptionValues;
import io.orchard.examples.Orchard;
import io.orchard.examples.match.Ranking;
import io.orchard.protocol.message.GameOverMessage;
import java.io.IOException;
import java.io.PrintStream;
import java.net.ConnectException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code ./orchard first-agent [--host H] [--port N] [--name NAME] [--resume-tokens FILE]}: plays
 * {@link FirstAgent} against a running server and prints the ranking when the game is over; like
 * the shipped agents, it keeps its resume token in a file of its own user. The launcher rebuilds
 * the project first when a source changed, so an edit of {@code FirstAgent.java} is played at once.
 */
@Command(name = "first-agent", abbreviateSynopsis = true, sortOptions = false,
        description = {"Play the tutorial's FirstAgent against a running server", "",
            "It plays examples/src/main/java/io/orchard/examples/firstagent/FirstAgent.java against a running Orchard "
                    + "server, and prints the ranking when the game is over (docs/tutorial.md)."},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n")
public final class FirstAgentCommand implements Callable<Integer> {

    @Option(names = "--host", paramLabel = "HOST", defaultValue = "localhost",
            description = "The server's host (default: ${DEFAULT-VALUE})")
    private String host;

    @Option(names = "--port", paramLabel = "N", defaultValue = "7557", converter = Port.class,
            description = "The server's port (default: ${DEFAULT-VALUE})")
    private int port;

    @Option(names = "--name", paramLabel = "NAME", defaultValue = "FirstAgent", converter = OptionValues.AgentName.class,
            description = "The agent's name in the world (default: ${DEFAULT-VALUE})")
    private String name;

    @Option(names = "--token", paramLabel = "SECRET", description = "The token the server requires, if any")
    private String token;

    @Option(names = "--resume-tokens", paramLabel = "FILE", defaultValue = "${sys:user.home}/.orchard/resume-tokens",
            description = "Keep the agent's resume token in FILE, readable by you alone, so that the same command run "
                    + "again after a dropped connection or a server restarted with --resume gets the agent back with "
                    + "its score (default: ${DEFAULT-VALUE})")
    private Path resumeTokens;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    private final PrintStream out;
    private final PrintStream err;

    /** Runs {@code ./orchard first-agent} with these arguments. */
    public static void main(String[] args) {
        Orchard.runAndExit("first-agent", args);
    }

    /** The {@code ./orchard first-agent} command, printing to these streams. */
    public FirstAgentCommand(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
    }

    @Override
    public Integer call() throws Exception {
        out.println(name + " is connecting to " + host + ":" + port);
        out.flush();
        try {
            FirstAgent agent = new FirstAgent(name);
            agent.keepResumeTokensIn(resumeTokens);
            GameOverMessage over = agent.run(host, port, token);
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
