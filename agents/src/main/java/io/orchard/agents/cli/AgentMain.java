package io.orchard.agents.cli;

import io.orchard.agents.AgentController;
import io.orchard.agents.AgentStats;
import io.orchard.agents.zoo.Species;
import io.orchard.protocol.cli.Options;
import io.orchard.protocol.cli.UsageException;
import io.orchard.protocol.message.GameOverMessage;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Score;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Consumer;

/**
 * The command lines that run the zoo's agents against a server.
 *
 * <ul>
 *   <li>{@code ./orchard agent --type dwarf [--name N] [--host H] [--port P] [--token T]}: one
 *       agent. Each line typed on the console is an instruction for it in English ("pick up the
 *       coconut on the table", "cross the bridge", "stop", "carry on"); what it says, answers
 *       included, is printed.
 *   <li>{@code ./orchard agents [--host H] [--port P] [--token T]}: all five, in one process,
 *       each on its own connection. A console line starting with an agent's name instructs that
 *       agent ("Dwarf: collect a banana", or "Guppy, stop").
 * </ul>
 *
 * <p>Both print the ranking and what each agent did when the game is over. The exit status is 0
 * when the game ended, 1 when an agent could not play (no server, a model that fails its check)
 * and 2 for a wrong command line.
 */
public final class AgentMain {

    static final String TYPES = String.join(", ",
            Arrays.stream(Species.values()).map(s -> s.name().toLowerCase(Locale.ROOT)).toList());

    static final Options AGENT = new Options("orchard agent",
            "Runs one of the paper's agents against an Orchard server.\nLines typed on the console are"
                    + " instructions for it in English, such as: pick up the coconut on the table | cross the bridge"
                    + " | go to the castle and then explore | follow Guppy | stop | carry on.")
            .value("type", "TYPE", "the agent: " + TYPES, null)
            .value("name", "NAME", "the agent's name in the world (default: its type's, as Dwarf)", null)
            .value("host", "HOST", "the server's host", "localhost")
            .value("port", "N", "the server's port", "7557")
            .value("token", "SECRET", "the token the server requires, if any", null);

    static final Options AGENTS = new Options("orchard agents",
            "Runs all five of the paper's agents against an Orchard server, each on its own connection.\n"
                    + "A console line 'Name: instruction' instructs one of them, as in 'Dwarf: collect a banana'"
                    + " or 'Guppy, stop'.")
            .value("host", "HOST", "the server's host", "localhost")
            .value("port", "N", "the server's port", "7557")
            .value("token", "SECRET", "the token the server requires, if any", null);

    private AgentMain() {}

    /** The help of {@code ./orchard agent}. */
    public static String agentHelp() {
        return AGENT.help();
    }

    /** The help of {@code ./orchard agents}. */
    public static String agentsHelp() {
        return AGENTS.help();
    }

    /**
     * Runs {@code ./orchard agent}.
     *
     * @param console where instructions are typed
     * @return the exit status
     * @throws UsageException naming a wrong option
     */
    public static int agent(List<String> args, InputStream console, PrintStream out, PrintStream err)
            throws UsageException, InterruptedException {
        Options.Parsed options = AGENT.parse(args);
        if (options.help()) {
            out.print(AGENT.help());
            return 0;
        }
        if (options.string("type") == null) {
            throw new UsageException("--type is required: one of " + TYPES);
        }
        Species species = species(options.string("type"));
        String name = options.string("name") == null ? species.agentName() : options.string("name");
        try {
            Checks.name(name, "--name");
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        String host = options.string("host");
        int port = options.integer("port", 1, 65535);
        AgentController agent = species.create(name);
        agent.addSpeechListener(text -> out.println(name + ": " + text));
        listen(console, agent::instruct);
        out.printf(Locale.ROOT, "%s (%s) is connecting to %s:%d; type instructions for it here.%n", name,
                species.name().toLowerCase(Locale.ROOT), host, port);
        try {
            GameOverMessage over = agent.run(host, port, options.string("token"));
            report(over, List.of(agent), out);
            return 0;
        } catch (IOException | IllegalArgumentException e) {
            err.println("orchard agent: " + e.getMessage());
            return 1;
        }
    }

    /**
     * Runs {@code ./orchard agents}.
     *
     * @return the exit status
     * @throws UsageException naming a wrong option
     */
    public static int agents(List<String> args, InputStream console, PrintStream out, PrintStream err)
            throws UsageException, InterruptedException {
        Options.Parsed options = AGENTS.parse(args);
        if (options.help()) {
            out.print(AGENTS.help());
            return 0;
        }
        String host = options.string("host");
        int port = options.integer("port", 1, 65535);
        String token = options.string("token");
        Map<String, AgentController> byName = new LinkedHashMap<>();
        for (Species species : Species.values()) {
            AgentController agent = species.create();
            agent.addSpeechListener(text -> out.println(agent.name() + ": " + text));
            byName.put(agent.name().toLowerCase(Locale.ROOT), agent);
        }
        listen(console, line -> route(line, byName, out));
        out.printf(Locale.ROOT, "%s are connecting to %s:%d; instruct one with 'Name: instruction'.%n",
                String.join(", ", byName.values().stream().map(AgentController::name).toList()), host, port);
        ExecutorService pool = Executors.newFixedThreadPool(byName.size(), runnable -> {
            Thread thread = new Thread(runnable, "orchard-agent");
            thread.setDaemon(true);
            return thread;
        });
        try {
            List<Future<GameOverMessage>> games = new ArrayList<>();
            for (AgentController agent : byName.values()) {
                games.add(pool.submit(() -> agent.run(host, port, token)));
            }
            GameOverMessage over = null;
            int status = 0;
            for (int i = 0; i < games.size(); i++) {
                try {
                    GameOverMessage one = games.get(i).get();
                    over = over == null ? one : over;
                } catch (ExecutionException e) {
                    AgentController agent = new ArrayList<>(byName.values()).get(i);
                    err.println("orchard agents: " + agent.name() + ": " + e.getCause().getMessage());
                    status = 1;
                }
            }
            report(over, List.copyOf(byName.values()), out);
            return status;
        } finally {
            byName.values().forEach(AgentController::stop);
            pool.shutdownNow();
        }
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

    private static Species species(String type) throws UsageException {
        try {
            return Species.named(type);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--type: " + e.getMessage());
        }
    }

    /** Hands every non-blank console line to {@code sink}, on a daemon thread. */
    private static void listen(InputStream console, Consumer<String> sink) {
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

    private static void report(GameOverMessage over, List<AgentController> agents, PrintStream out) {
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
