package io.orchard.agents.cli;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Species;
import io.orchard.cli.CommandLineErrors;
import io.orchard.protocol.message.GameOverMessage;
import java.io.InputStream;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code ./orchard agents}: all five agents of the zoo, each on its own connection. */
@Command(name = "agents", abbreviateSynopsis = true, sortOptions = false,
        description = {"Run the paper's five agents, each on its own connection", "",
            "A console line 'Name: instruction' instructs one of them, as in 'Dwarf: collect a banana' or "
                    + "'Guppy, stop'."},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n")
final class AgentsCommand implements Callable<Integer> {

    @Mixin
    private ServerAddress server;

    @Mixin
    private ResumeTokensOption resumeTokens;

    @Mixin
    private LanguageOption language;

    @Mixin
    private LanguageModelOptions languageModel;

    @Mixin
    private NextGamesOption nextGames;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    private final InputStream console;
    private final PrintStream out;
    private final PrintStream err;

    AgentsCommand(InputStream console, PrintStream out, PrintStream err) {
        this.console = console;
        this.out = out;
        this.err = err;
    }

    @Override
    public Integer call() throws InterruptedException {
        Map<String, AgentController> byName = new LinkedHashMap<>();
        for (Species species : Species.values()) {
            AgentController agent = agent(species);
            byName.put(agent.name().toLowerCase(Locale.ROOT), agent);
        }
        AgentMain.listen(console, line -> {
            synchronized (byName) {
                AgentMain.route(line, byName, out);
            }
        });
        out.printf(Locale.ROOT, "%s are connecting to %s:%d; instruct one with 'Name: instruction'.%n",
                String.join(", ", byName.values().stream().map(AgentController::name).toList()), server.host,
                server.port);
        ExecutorService pool = Executors.newFixedThreadPool(byName.size(), runnable -> {
            Thread thread = new Thread(runnable, "orchard-agent");
            thread.setDaemon(true);
            return thread;
        });
        try {
            List<Future<GameOverMessage>> games = new ArrayList<>();
            for (Species species : Species.values()) {
                games.add(pool.submit(() -> play(species, byName)));
            }
            GameOverMessage over = null;
            int status = 0;
            for (int i = 0; i < games.size(); i++) {
                try {
                    GameOverMessage one = games.get(i).get();
                    over = over == null ? one : over;
                } catch (ExecutionException e) {
                    err.println("orchard agents: " + Species.values()[i].agentName() + ": "
                            + e.getCause().getMessage());
                    status = CommandLineErrors.FAILED;
                }
            }
            synchronized (byName) {
                AgentMain.report(over, List.copyOf(byName.values()), out);
            }
            return status;
        } finally {
            synchronized (byName) {
                byName.values().forEach(AgentController::stop);
            }
            pool.shutdownNow();
        }
    }

    /** The agent of {@code species}'s games: its first, and with --next-games each next one, by a new agent. */
    private GameOverMessage play(Species species, Map<String, AgentController> byName) throws Exception {
        String key = species.agentName().toLowerCase(Locale.ROOT);
        AgentController agent;
        synchronized (byName) {
            agent = byName.get(key);
        }
        while (true) {
            GameOverMessage over = agent.run(server.host, server.port, server.token);
            if (!nextGames.another(agent)) {
                return over;
            }
            agent = agent(species);
            synchronized (byName) {
                byName.put(key, agent);
            }
        }
    }

    private AgentController agent(Species species) {
        AgentController agent = species.create();
        resumeTokens.keep(agent);
        language.apply(agent);
        languageModel.apply(agent);
        nextGames.apply(agent);
        agent.addSpeechListener(text -> out.println(agent.name() + ": " + text));
        return agent;
    }
}
