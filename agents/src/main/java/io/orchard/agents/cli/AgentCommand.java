package io.orchard.agents.cli;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Species;
import io.orchard.cli.CommandLineErrors;
import io.orchard.protocol.message.GameOverMessage;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code ./orchard agent}: one agent of the zoo, instructed from the console. */
@Command(name = "agent", abbreviateSynopsis = true, sortOptions = false,
        description = {"Run one of the paper's agents against a running server", "",
            "Lines typed on the console are instructions for it in English, such as: pick up the coconut on the "
                    + "table | cross the bridge | go to the castle and then explore | follow Guppy | stop | carry on."},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n")
final class AgentCommand implements Callable<Integer> {

    @Option(names = "--type", paramLabel = "TYPE", converter = CommandLines.Type.class,
            completionCandidates = CommandLines.Type.class, description = "The agent: ${COMPLETION-CANDIDATES}")
    private Species species;

    @Option(names = "--name", paramLabel = "NAME", converter = CommandLines.Name.class,
            description = "The agent's name in the world (default: its type's, as Dwarf)")
    private String name;

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

    @Spec
    private CommandSpec spec;

    private final InputStream console;
    private final PrintStream out;
    private final PrintStream err;

    AgentCommand(InputStream console, PrintStream out, PrintStream err) {
        this.console = console;
        this.out = out;
        this.err = err;
    }

    @Override
    public Integer call() throws InterruptedException {
        if (species == null) {
            throw new ParameterException(spec.commandLine(), "missing required option '--type' (expected one of "
                    + String.join(", ", new CommandLines.Type()) + ")");
        }
        String name = this.name == null ? species.agentName() : this.name;
        AtomicReference<AgentController> agent = new AtomicReference<>(agent(name));
        AgentMain.listen(console, text -> agent.get().instruct(text));
        out.printf(Locale.ROOT, "%s (%s) is connecting to %s:%d; type instructions for it here.%n", name,
                species.name().toLowerCase(Locale.ROOT), server.host, server.port);
        try {
            while (true) {
                GameOverMessage over = agent.get().run(server.host, server.port, server.token);
                AgentMain.report(over, List.of(agent.get()), out);
                if (!nextGames.another(agent.get())) {
                    return 0;
                }
                agent.set(agent(name));
            }
        } catch (IOException | IllegalArgumentException e) {
            err.println("orchard agent: " + e.getMessage());
            return CommandLineErrors.FAILED;
        }
    }

    private AgentController agent(String name) {
        AgentController agent = species.create(name);
        resumeTokens.keep(agent);
        language.apply(agent);
        languageModel.apply(agent);
        nextGames.apply(agent);
        agent.addSpeechListener(text -> out.println(name + ": " + text));
        return agent;
    }
}
