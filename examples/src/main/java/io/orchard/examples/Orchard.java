package io.orchard.examples;

import io.orchard.examples.demo.DemoCommand;
import io.orchard.examples.embedded.EmbeddedCommand;
import io.orchard.examples.firstagent.FirstAgentCommand;
import io.orchard.examples.schema.ProtocolSchemaCommand;
import io.orchard.examples.tournament.TournamentCommand;
import io.orchard.protocol.ProtocolVersion;
import io.orchard.protocol.cli.UsageException;
import io.orchard.server.Version;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The {@code orchard} launcher: {@code ./orchard <command> [options]} runs one of the
 * {@linkplain #COMMANDS commands}. With no arguments, {@code --help} or {@code help} it lists them;
 * {@code ./orchard <command> --help} (or {@code ./orchard help <command>}) shows one command's
 * options; {@code --version} prints the version of Orchard and of the protocol it speaks.
 *
 * <p>The exit status is 0 on success, 1 when a command fails and 2 when the command line is wrong.
 */
public final class Orchard {

    /** The launcher's commands, in the order its help lists them. A new command is added here. */
    static final List<Command> COMMANDS = List.of(
            new DemoCommand(),
            new ServerCommand(),
            new ViewerCommand(),
            new AgentCommand(),
            new AgentsCommand(),
            new FirstAgentCommand(),
            new TournamentCommand(),
            new EmbeddedCommand(),
            new ParseCommand(),
            new ProtocolSchemaCommand());

    /** How the launcher is started, as the help shows it. */
    static final String PROGRAM = "./orchard";

    static final int OK = 0;
    static final int FAILURE = 1;
    static final int USAGE = 2;

    private static final String HELP = "help";

    private final Map<String, Command> commands = new LinkedHashMap<>();

    /**
     * A launcher of these commands.
     *
     * @throws IllegalArgumentException when two commands share a name, or a name is blank, starts
     *                                  with '-' or is "help"
     */
    Orchard(List<Command> commands) {
        for (Command command : commands) {
            String name = command.name();
            if (name.isBlank() || name.startsWith("-") || name.equals(HELP)) {
                throw new IllegalArgumentException("command name must be a word other than 'help', was '" + name
                        + "' (" + command.getClass().getName() + ")");
            }
            Command previous = this.commands.putIfAbsent(name, command);
            if (previous != null) {
                throw new IllegalArgumentException("command name '" + name + "' is taken twice: by "
                        + previous.getClass().getName() + " and " + command.getClass().getName());
            }
        }
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

    /** Runs the launcher on these arguments, printing to these streams, and returns the exit status. */
    static int run(String[] args, PrintStream out, PrintStream err) {
        return new Orchard(COMMANDS).run(List.of(args), out, err);
    }

    int run(List<String> args, PrintStream out, PrintStream err) {
        if (args.isEmpty() || isHelp(args.get(0))) {
            printHelp(out);
            return OK;
        }
        String first = args.get(0);
        if (first.equals(HELP)) {
            return args.size() == 1 ? printHelp(out) : commandHelp(args.get(1), out, err);
        }
        if (first.equals("--version")) {
            out.println("orchard " + version() + " (protocol " + ProtocolVersion.CURRENT + ")");
            return OK;
        }
        Command command = commands.get(first);
        if (command == null) {
            return unknown(first, err);
        }
        List<String> rest = args.subList(1, args.size());
        if (rest.stream().anyMatch(Orchard::isHelp)) {
            out.print(command.help());
            return OK;
        }
        return runCommand(command, rest, out, err);
    }

    /** The version of Orchard, as the build stamped it. */
    static String version() {
        return Version.current();
    }

    private static int runCommand(Command command, List<String> args, PrintStream out, PrintStream err) {
        try {
            return command.run(args, out, err);
        } catch (UsageException e) {
            err.println("orchard " + command.name() + ": " + e.getMessage());
            err.println("Run " + PROGRAM + " " + command.name() + " --help for its options.");
            return USAGE;
        } catch (Exception e) {
            err.println("orchard " + command.name() + ": " + (e.getMessage() == null ? e : e.getMessage()));
            if (e instanceof RuntimeException) {
                e.printStackTrace(err); // a defect rather than a condition the message explains
            }
            return FAILURE;
        }
    }

    private int commandHelp(String name, PrintStream out, PrintStream err) {
        Command command = commands.get(name);
        if (command == null) {
            return unknown(name, err);
        }
        out.print(command.help());
        return OK;
    }

    private int unknown(String word, PrintStream err) {
        err.println("orchard: unknown " + (word.startsWith("-") ? "option" : "command") + " '" + word
                + "'; expected one of the commands below");
        err.println();
        printCommands(err);
        err.println();
        err.println("Run " + PROGRAM + " --help for usage.");
        return USAGE;
    }

    private int printHelp(PrintStream out) {
        out.println("Orchard: an open virtual environment for autonomous, instructable agents.");
        out.println();
        out.println("Usage: " + PROGRAM + " <command> [options]");
        out.println();
        printCommands(out);
        out.println();
        out.println("Options:");
        printRow(out, "--version", "Print the version of Orchard and of its protocol");
        printRow(out, "--help", "Show this help");
        out.println();
        out.println("Run " + PROGRAM + " <command> --help for the options of a command.");
        return OK;
    }

    private void printCommands(PrintStream out) {
        out.println("Commands:");
        for (Command command : commands.values()) {
            printRow(out, command.name(), command.summary());
        }
        printRow(out, HELP, "Show this help, or a command's: " + HELP + " <command>");
    }

    private void printRow(PrintStream out, String name, String summary) {
        out.println("  " + name + " ".repeat(nameWidth() - name.length() + 2) + summary);
    }

    private int nameWidth() {
        List<String> names = new ArrayList<>(commands.keySet());
        names.add("--version");
        return names.stream().mapToInt(String::length).max().orElse(0);
    }

    private static boolean isHelp(String arg) {
        return arg.equals("--help") || arg.equals("-h");
    }
}
