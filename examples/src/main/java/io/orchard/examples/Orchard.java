package io.orchard.examples;

import io.orchard.agents.cli.AgentMain;
import io.orchard.cluster.NodeMain;
import io.orchard.examples.demo.DemoCommand;
import io.orchard.examples.embedded.EmbeddedCommand;
import io.orchard.examples.firstagent.FirstAgentCommand;
import io.orchard.examples.schema.ProtocolSchemaCommand;
import io.orchard.examples.tournament.TournamentCommand;
import io.orchard.protocol.ProtocolVersion;
import io.orchard.server.ServerMain;
import io.orchard.server.Version;
import io.orchard.viewer.ViewerMain;
import java.io.InputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.HelpCommand;
import picocli.CommandLine.IVersionProvider;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * The {@code orchard} launcher: {@code ./orchard <command> [options]} runs one of its
 * {@linkplain #commands commands}, each a picocli command. With no arguments, {@code --help} or
 * {@code help} it lists them; {@code ./orchard <command> --help} (or {@code ./orchard help
 * <command>}) shows one command's options; {@code --version} prints the version of Orchard and of
 * the protocol it speaks; {@code completion} prints a bash completion script.
 *
 * <p>The exit status is 0 on success, 1 when a command fails and 2 when the command line is wrong.
 */
@Command(name = "orchard", customSynopsis = "orchard <command> [OPTIONS]", versionProvider = Orchard.Versions.class,
        description = "Orchard: an open virtual environment for autonomous, instructable agents",
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n", commandListHeading = "%nCommands:%n",
        footerHeading = "%n", footer = "Run ./orchard <command> --help for the options of a command.")
public final class Orchard implements Callable<Integer> {

    /** The summary of the {@code help} command, in the style of the others. */
    static final String HELP_SUMMARY = "Show this help, or a command's: help <command>";

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    @Option(names = "--version", versionHelp = true,
            description = "Print the version of Orchard and of its protocol and exit")
    private boolean version;

    @Spec
    private CommandSpec spec;

    private Orchard() {
    }

    public static void main(String[] args) {
        int status = run(args, System.out, System.err);
        System.out.flush();
        System.exit(status);
    }

    /**
     * Runs one command as {@code ./orchard <command> args...} does, then exits with its status: the
     * {@code main} of each example's command, so that an IDE can run it as it runs any main class.
     */
    public static void runAndExit(String command, String[] args) {
        List<String> all = new ArrayList<>(List.of(command));
        all.addAll(List.of(args));
        main(all.toArray(String[]::new));
    }

    /**
     * Runs the launcher on these arguments, printing to these streams, and returns the exit status:
     * {@code ./orchard} without the JVM's exit, for tests and for programs that embed the commands.
     */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return launcher(commands(System.in, out, err), out, err).execute(args);
    }

    /**
     * The launcher's commands, in the order its help lists them, before {@code help}. A new command
     * is added here.
     */
    static List<CommandLine> commands(InputStream console, PrintStream out, PrintStream err) {
        return List.of(
                new CommandLine(new DemoCommand(out, err)),
                ServerMain.command(console, out, err),
                NodeMain.command(console, out, err),
                ViewerMain.command(out, err),
                AgentMain.agentCommand(console, out, err),
                AgentMain.agentsCommand(console, out, err),
                new CommandLine(new FirstAgentCommand(out, err)),
                new CommandLine(new TournamentCommand(out)),
                new CommandLine(new EmbeddedCommand(out)),
                new CommandLine(new ParseCommand(out)),
                new CommandLine(new ModelInfoCommand(out)),
                new CommandLine(new ProtocolSchemaCommand(out)),
                new CommandLine(new CompletionCommand(out)));
    }

    /**
     * The launcher of these commands and {@code help}, printing to these streams.
     *
     * @throws CommandLine.DuplicateNameException when two commands share a name
     */
    static CommandLine launcher(List<CommandLine> commands, PrintStream out, PrintStream err) {
        CommandLine orchard = new CommandLine(new Orchard());
        commands.forEach(orchard::addSubcommand);
        orchard.addSubcommand(new HelpCommand());
        orchard.getSubcommands().get("help").getCommandSpec().usageMessage().header(HELP_SUMMARY);
        LauncherErrors errors = new LauncherErrors(err);
        return orchard.setOut(new PrintWriter(out, true)).setErr(new PrintWriter(err, true))
                .setParameterExceptionHandler(errors).setExecutionExceptionHandler(errors);
    }

    /** Without a command, the launcher shows its help. */
    @Override
    public Integer call() {
        spec.commandLine().usage(spec.commandLine().getOut());
        return 0;
    }

    /** The version of Orchard, as the build stamped it. */
    static String version() {
        return Version.current();
    }

    /** What {@code --version} prints. */
    static final class Versions implements IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] {"orchard " + version() + " (protocol " + ProtocolVersion.CURRENT + ")"};
        }
    }
}
