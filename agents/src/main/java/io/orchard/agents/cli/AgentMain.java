package io.orchard.agents.cli;

import io.orchard.agents.AgentController;
import io.orchard.agents.AgentStats;
import io.orchard.cli.CommandLineErrors;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.value.Score;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;
import picocli.CommandLine;

/**
 * The command lines that run the zoo's agents against a server.
 *
 * <ul>
 *   <li>{@code ./orchard agent --type dwarf [--name N] [--host H] [--port P] [--token T]
 *       [--resume-tokens FILE]}: one agent. Each line typed on the console is an instruction for it
 *       in English ("pick up the coconut on the table", "cross the bridge", "stop", "carry on");
 *       what it says, answers included, is printed.
 *   <li>{@code ./orchard agents [--host H] [--port P] [--token T] [--resume-tokens FILE]}: all
 *       five, in one process, each on its own connection. A console line starting with an agent's
 *       name instructs that agent ("Dwarf: collect a banana", or "Guppy, stop").
 * </ul>
 *
 * <p>Both keep their agents' resume tokens in a file readable by its owner only,
 * {@code ~/.orchard/resume-tokens} unless {@code --resume-tokens FILE} names another, and present
 * them when they register: run again after a dropped connection, or after the server was restarted
 * with {@code --resume}, the same command gets the agents back with their places and scores.
 *
 * <p>Both print the ranking and what each agent did when the game is over. The exit status is 0
 * when the game ended, 1 when an agent could not play (no server, a model that fails its check)
 * and 2 for a wrong command line, whose message names the option, the value and what was expected.
 * {@link #agentCommand} and {@link #agentsCommand} hand both to a launcher as its subcommands.
 */
public final class AgentMain {

    private AgentMain() {}

    /** The help of {@code ./orchard agent}. */
    public static String agentHelp() {
        return agentCommand(InputStream.nullInputStream(), System.out, System.err).setCommandName("orchard agent")
                .getUsageMessage(CommandLine.Help.Ansi.OFF);
    }

    /** The help of {@code ./orchard agents}. */
    public static String agentsHelp() {
        return agentsCommand(InputStream.nullInputStream(), System.out, System.err).setCommandName("orchard agents")
                .getUsageMessage(CommandLine.Help.Ansi.OFF);
    }

    /**
     * Runs {@code ./orchard agent}.
     *
     * @param console where instructions are typed
     * @return the exit status: 0 when the game ended, 1 when the agent could not play, 2 for a
     *         wrong command line (printed on {@code err}, naming the option and the value)
     */
    public static int agent(List<String> args, InputStream console, PrintStream out, PrintStream err) {
        return CommandLineErrors.execute(agentCommand(console, out, err).setCommandName("orchard agent"), args, err);
    }

    /**
     * Runs {@code ./orchard agents}.
     *
     * @return the exit status, as {@link #agent} returns it
     */
    public static int agents(List<String> args, InputStream console, PrintStream out, PrintStream err) {
        return CommandLineErrors.execute(agentsCommand(console, out, err).setCommandName("orchard agents"), args, err);
    }

    /**
     * {@code agent} as a picocli command, for a launcher to add as its subcommand: it reads
     * instructions from {@code console} and prints to {@code out} and {@code err}.
     */
    public static CommandLine agentCommand(InputStream console, PrintStream out, PrintStream err) {
        return new CommandLine(new AgentCommand(console, out, err)).setOut(new PrintWriter(out, true))
                .setErr(new PrintWriter(err, true));
    }

    /** {@code agents} as a picocli command, for a launcher to add as its subcommand, as {@link #agentCommand}. */
    public static CommandLine agentsCommand(InputStream console, PrintStream out, PrintStream err) {
        return new CommandLine(new AgentsCommand(console, out, err)).setOut(new PrintWriter(out, true))
                .setErr(new PrintWriter(err, true));
    }

    /** A console line for one of several agents: "Name: text", "Name, text" or "Name text". */
    static void route(String line, Map<String, AgentController> byName, PrintStream out) {
        String trimmed = line.strip();
        if (trimmed.isEmpty()) {
            return;
        }
        int split = trimmed.indexOf(':');
        String first = split > 0 ? trimmed.substring(0, split) : trimmed.split("\\s+", 2)[0];
        String rest = split > 0 ? trimmed.substring(split + 1) : trimmed.substring(first.length());
        // "Guppy, stop": the name ends with a comma, and the agent reads the rest
        AgentController agent = byName.get(first.strip().replaceAll(",$", "").toLowerCase(Locale.ROOT));
        if (agent == null || rest.isBlank()) {
            out.println("Start the line with the agent's name, as in 'Dwarf: collect a banana'; agents: "
                    + String.join(", ", byName.values().stream().map(AgentController::name).toList()));
            return;
        }
        agent.instruct(rest.strip());
    }

    /** Hands every non-blank console line to {@code sink}, on a daemon thread. */
    static void listen(InputStream console, Consumer<String> sink) {
        Thread reader = new Thread(() -> {
            try (BufferedReader in = new BufferedReader(new InputStreamReader(console, StandardCharsets.UTF_8))) {
                String line;
                while ((line = in.readLine()) != null) {
                    if (!line.isBlank()) {
                        try {
                            sink.accept(line.strip());
                        } catch (IllegalArgumentException e) {
                            // longer than an instruction may be: skip it
                        }
                    }
                }
            } catch (IOException e) {
                // the console closed: the agents play on
            }
        }, "orchard-agent-console");
        reader.setDaemon(true);
        reader.start();
    }

    static void report(GameOverMessage over, List<AgentController> agents, PrintStream out) {
        if (over == null) {
            return;
        }
        out.println("Game over (" + over.reason() + "). Ranking:");
        int place = 1;
        for (Score score : over.ranking()) {
            out.printf(Locale.ROOT, "%3d. %-16s %4d points  %3d fruit%n", place++, score.agent(), score.points(),
                    score.fruit());
        }
        for (AgentController agent : agents) {
            AgentStats stats = agent.stats();
            out.printf(Locale.ROOT, "%s: %d moves (%d refused by an obstacle, %.1f %%), %d grasps, %d won%n",
                    agent.name(), stats.movesSent(), stats.obstacleRejections(), 100 * stats.obstacleRejectionRate(),
                    stats.graspsSent(), stats.graspsWon());
        }
    }
}
