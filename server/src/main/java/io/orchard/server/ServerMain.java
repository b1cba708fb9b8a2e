package io.orchard.server;

import io.orchard.cli.CommandLineErrors;
import io.orchard.cli.Seed;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Score;
import io.orchard.server.sim.Phase;
import io.orchard.server.world.WorldGenerator;
import io.orchard.server.world.scenario.ScenarioFile;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * The world server's command line: {@code ./orchard server [options]}. It prints the game's state
 * once a second and the ranking at the end, and reads commands from its console: {@code start},
 * {@code pause}, {@code continue}, {@code status}, {@code checkpoint [FILE]}, {@code stop}. When its
 * standard input ends (started with {@code < /dev/null}, or in the background) it says so once and
 * runs on, to be stopped by a signal, unless {@code --stop-on-stdin-close} asks it to stop.
 *
 * <p>Run on its own ({@link #main}, {@link #run}) it is {@code orchard server}; {@link #command}
 * hands it to a launcher as its subcommand {@code server}. Exit status: 0 done, 1 failed, 2 bad
 * command line.
 */
@Command(name = "server", abbreviateSynopsis = true, sortOptions = false,
        description = {"Run the world server (the world, the game, the protocol)", "",
            "It holds the world and the game and speaks the protocol on one TCP port; it prints the game's state "
                    + "every second and the ranking when the game is over."},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n", footerHeading = "%n",
        footer = {"Console commands: start, pause, continue, status, checkpoint [FILE], restart [SEED], stop. When "
                + "standard input ends, the server runs on (stop it with Ctrl-C or SIGTERM) unless "
                + "--stop-on-stdin-close is given.",
            "",
            "Environment: " + ServerMain.OPERATOR_TOKEN_VARIABLE + " gives the operator token when --operator-token "
                    + "does not, out of sight of other users' ps."})
public final class ServerMain implements Callable<Integer> {

    /** The environment variable that gives the operator token when the command line does not. */
    public static final String OPERATOR_TOKEN_VARIABLE = "ORCHARD_OPERATOR_TOKEN";

    @Option(names = "--port", paramLabel = "N", defaultValue = "" + WorldServer.DEFAULT_PORT,
            converter = CommandLines.Port.class, description = "TCP port; 0 picks a free one (default: ${DEFAULT-VALUE})")
    private int port;

    @Option(names = "--bind", paramLabel = "ADDRESS", defaultValue = "127.0.0.1",
            description = "Address to listen on; 0.0.0.0 for every interface (default: ${DEFAULT-VALUE})")
    private String bind;

    @Option(names = "--http-port", paramLabel = "N", converter = CommandLines.Port.class,
            description = "Also serve the browser viewer, a page at http://ADDRESS:N/ (0 picks a free port; off unless"
                    + " given; needs the web module, which ./orchard has)")
    private Integer httpPort;

    @Option(names = "--seed", paramLabel = "N", converter = Seed.class,
            description = "Seed of the world; drawn and printed when absent")
    private Long seed;

    @Option(names = "--clock", paramLabel = "MODE", defaultValue = "realtime", converter = CommandLines.Clock.class,
            completionCandidates = CommandLines.Clock.class,
            description = "The clock: realtime, or lockstep, where a tick ends when every agent has ended its turn "
                    + "(default: ${DEFAULT-VALUE})")
    private ClockMode clock;

    @Option(names = "--tick-rate", paramLabel = "N", defaultValue = "20", converter = CommandLines.TickRate.class,
            description = "Ticks per simulated second (default: ${DEFAULT-VALUE})")
    private int tickRate;

    @Option(names = "--wait-for", paramLabel = "N", defaultValue = "0", converter = CommandLines.WaitFor.class,
            description = "Start the game when N agents have registered; 0: at the first (default: ${DEFAULT-VALUE})")
    private int waitFor;

    @Option(names = "--time-limit", paramLabel = "SECONDS", defaultValue = "300",
            converter = CommandLines.TimeLimit.class,
            description = "Length of the game in simulated seconds (default: ${DEFAULT-VALUE})")
    private double timeLimit;

    @Option(names = "--turn-deadline", paramLabel = "SECONDS", defaultValue = "2",
            converter = CommandLines.TurnDeadline.class,
            description = "Lockstep: how long a tick waits for an agent's turn (wall clock); an agent that misses it 3 "
                    + "times in a row is no longer waited for until it is in time again (default: ${DEFAULT-VALUE})")
    private double turnDeadline;

    @Option(names = "--scenario", paramLabel = "FILE",
            description = "Load the world from a scenario file instead of generating it")
    private Path scenario;

    @Option(names = "--write-scenario", paramLabel = "FILE",
            description = "Write the world (generated from --seed) as a scenario file and exit")
    private Path writeScenario;

    @Option(names = "--record", paramLabel = "FILE",
            description = "Record every message accepted and sent, as newline-delimited JSON")
    private Path record;

    @Option(names = "--token", paramLabel = "SECRET",
            description = "Require clients to present this token in their hello")
    private String token;

    @Option(names = "--operator-token", paramLabel = "SECRET", defaultValue = "${env:" + OPERATOR_TOKEN_VARIABLE + "}",
            description = "Let a client that presents this token in its hello start, pause and resume the game "
                    + "(GameControl); without it only this console does. Also read from " + OPERATOR_TOKEN_VARIABLE)
    private String operatorToken;

    @Option(names = "--checkpoint", paramLabel = "FILE",
            description = "Save the whole game to FILE: when fruit is collected, at the end, on the console's "
                    + "checkpoint command, every --checkpoint-every seconds and when asked to end (Ctrl-C, SIGTERM)")
    private Path checkpoint;

    @Option(names = "--checkpoint-every", paramLabel = "SECONDS", defaultValue = "60",
            converter = CommandLines.CheckpointEvery.class,
            description = "With --checkpoint, also save every SECONDS of wall-clock time, the most play a crash "
                    + "loses; 0 for never (default: ${DEFAULT-VALUE})")
    private double checkpointEvery;

    @Option(names = "--resume", paramLabel = "FILE",
            description = "Continue the game saved in a checkpoint FILE (its world, seed, clock, scores; its agents "
                    + "wait for their controllers' resume tokens)")
    private Path resume;

    @Option(names = "--name-reservation", paramLabel = "SECONDS", defaultValue = "60",
            converter = CommandLines.NameReservation.class,
            description = "How long a dropped agent's name and score stay its controller's: meanwhile only its "
                    + "resume token registers the name; 0 frees it at once (default: ${DEFAULT-VALUE})")
    private double nameReservation;

    @Option(names = "--quiet", description = "Do not print the status line every second")
    private boolean quiet;

    @Option(names = "--keep-serving",
            description = "Stay when a game is over, for the next: the operator's GameControl restart, or the "
                    + "console's restart, starts it on the same connections; by default the server exits after one "
                    + "game, and refuses restarts")
    private boolean keepServing;

    @Option(names = "--stop-on-stdin-close",
            description = "End the game and exit when standard input ends (for a program that starts the server "
                    + "and holds its input); by default the server runs on")
    private boolean stopOnStdinClose;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    @Spec
    private CommandSpec spec;

    private final InputStream console;
    private final PrintStream out;
    private final PrintStream err;

    private ServerMain(InputStream console, PrintStream out, PrintStream err) {
        this.console = console;
        this.out = out;
        this.err = err;
    }

    /** Runs the server with the command line {@code args} and exits with its status. */
    public static void main(String[] args) {
        System.exit(run(Arrays.asList(args), System.in, System.out, System.err));
    }

    /** Runs the command line as {@code orchard server}; returns the process exit status. */
    public static int run(List<String> args, InputStream console, PrintStream out, PrintStream err) {
        return CommandLineErrors.execute(command(console, out, err).setCommandName("orchard server"), args, err);
    }

    /** The help text of the server's command line. */
    public static String help() {
        return command(InputStream.nullInputStream(), System.out, System.err).setCommandName("orchard server")
                .getUsageMessage(CommandLine.Help.Ansi.OFF);
    }

    /**
     * The command line as a picocli command named {@code server}, for a launcher to add as its
     * subcommand: it reads console commands from {@code console} and prints to {@code out} and
     * {@code err}.
     */
    public static CommandLine command(InputStream console, PrintStream out, PrintStream err) {
        return new CommandLine(new ServerMain(console, out, err)).setOut(new PrintWriter(out, true))
                .setErr(new PrintWriter(err, true));
    }

    /** Runs the server as the options say; picocli calls it once they are parsed. */
    @Override
    @SuppressWarnings("try") // the shutdown hook is a resource only so that it is removed when the game ends
    public Integer call() throws Exception {
        WorldServer.Builder builder = WorldServer.builder();
        try {
            configure(builder);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage(), e);
        }
        if (writeScenario != null) {
            long seed = this.seed != null ? this.seed
                    : java.util.concurrent.ThreadLocalRandom.current().nextLong(1, 1L << 48);
            ScenarioFile.write(WorldGenerator.standard(seed).generate().toScenario(), writeScenario);
            out.println("wrote the world of seed " + seed + " to " + writeScenario);
            return 0;
        }
        try (WorldServer server = builder.start();
             ShutdownSave onEnd = ShutdownSave.install(server, checkpoint != null, out)) {
            out.printf(Locale.ROOT, "Orchard server %s listening on port %d, seed %d, %s clock%n", Version.current(),
                    server.port(), server.seed(), resume != null ? "the saved game's" : clock.wireName());
            server.httpPort().ifPresent(http -> out.println("browser viewer at " + pageAddress(bind, http)));
            if (resume != null) {
                out.println("resumed from " + resume + ": " + server.status());
            }
            java.util.concurrent.CountDownLatch leaving = new java.util.concurrent.CountDownLatch(1);
            java.util.concurrent.CompletableFuture<List<Score>> first = server.gameOver(); // before any restart
            Thread commands = new Thread(() -> readCommands(server, console, out, stopOnStdinClose,
                    leaving::countDown), "orchard-console");
            commands.setDaemon(true);
            commands.start();
            serve(server, first, leaving);
        } catch (IOException e) {
            err.println("orchard server: " + e.getMessage());
            return 1;
        }
        return 0;
    }

    /**
     * Until the game is over, printing the status every second unless quiet, and its ranking then;
     * with --keep-serving, game after game until the console stops the server.
     */
    private void serve(WorldServer server, java.util.concurrent.CompletableFuture<List<Score>> first,
                       java.util.concurrent.CountDownLatch leaving) throws InterruptedException {
        java.util.concurrent.CompletableFuture<List<Score>> game = first;
        while (true) {
            try {
                printRanking(game.get(1, java.util.concurrent.TimeUnit.SECONDS), out);
                if (!keepServing) {
                    return;
                }
                // The next game is the operator's to start; the console's stop ends the server.
                while (server.gameOver() == game) {
                    // A restart before the stop has made its game by the time the stop is told.
                    if (leaving.await(50, java.util.concurrent.TimeUnit.MILLISECONDS) && server.gameOver() == game) {
                        return;
                    }
                }
                game = server.gameOver();
            } catch (java.util.concurrent.TimeoutException e) {
                if (!quiet) {
                    out.println(server.status());
                }
            } catch (java.util.concurrent.CancellationException | java.util.concurrent.ExecutionException e) {
                return;
            }
        }
    }

    private void configure(WorldServer.Builder builder) {
        if (httpPort != null) {
            builder.httpPort(httpPort);
        }
        builder.port(port).bind(bind)
                .clock(clock)
                .tickRate(tickRate)
                .waitFor(waitFor)
                .timeLimit(timeLimit)
                .lockstepDeadline(Duration.ofMillis(Math.round(turnDeadline * 1000)));
        if (seed != null) {
            builder.seed(seed);
        }
        if (scenario != null) {
            builder.scenario(scenario);
        }
        if (record != null) {
            builder.record(record);
        }
        if (token != null) {
            builder.token(token);
        }
        if (operatorToken != null) {
            builder.operatorToken(operatorToken);
        }
        if (checkpoint != null) {
            builder.checkpoint(checkpoint, checkpointEvery > 0
                    ? Duration.ofMillis((long) (checkpointEvery * 1000)) : null);
        }
        if (resume != null) {
            builder.resume(resume);
        }
        builder.nameReservation(Duration.ofMillis((long) (nameReservation * 1000)));
        if (!keepServing) {
            builder.oneGame("this server stops when its game is over: start it with --keep-serving to restart games");
        }
    }

    private static void readCommands(WorldServer server, InputStream console, PrintStream out,
                                     boolean stopOnClose, Runnable leave) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(console, StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                String command = line.strip().toLowerCase(Locale.ROOT);
                if (command.startsWith("checkpoint")) {
                    checkpoint(server, line.strip().substring("checkpoint".length()).strip(), out);
                    continue;
                }
                if (command.startsWith("restart")) {
                    restart(server, command.substring("restart".length()).strip(), out);
                    continue;
                }
                switch (command) {
                    case "" -> { }
                    case "start" -> server.startGame();
                    case "pause", "continue", "resume" -> {
                        boolean paused = server.phase() == Phase.PAUSED;
                        if (command.equals("pause") == paused) {
                            out.println(paused ? "already paused" : "not paused");
                        } else if (paused) {
                            server.resumeGame();
                        } else {
                            server.pauseGame();
                        }
                    }
                    case "status" -> out.println(server.status());
                    case "stop", "quit" -> {
                        server.endGame("stopped from the console");
                        leave.run();
                    }
                    default -> out.println("unknown command '" + command
                            + "'; commands: start, pause, continue, status, checkpoint [FILE], restart [SEED], stop");
                }
            }
        } catch (IOException e) {
            // Unreadable input is closed input.
        }
        consoleClosed(server, out, stopOnClose);
        if (stopOnClose) {
            leave.run();
        }
    }

    private static void restart(WorldServer server, String seed, PrintStream out) {
        long next;
        try {
            next = seed.isEmpty() ? server.seed() : Long.parseLong(seed);
        } catch (NumberFormatException e) {
            out.println("restart takes a whole number as the new game's seed, was '" + seed + "'");
            return;
        }
        try {
            server.restart(next);
            out.println("restarting: a new game of seed " + next + " waits for its agents");
        } catch (IllegalStateException e) {
            out.println("cannot restart: " + e.getMessage());
        }
    }

    /**
     * Standard input ended: a server started with {@code < /dev/null} or in the background is still
     * wanted, so it says so and runs on, unless told to stop.
     */
    private static void consoleClosed(WorldServer server, PrintStream out, boolean stop) {
        if (stop) {
            out.println("console input closed: the game ends and the server stops (--stop-on-stdin-close)");
            server.endGame("the server's console input closed");
        } else {
            out.println("console input closed: the server runs on without its console; stop it with Ctrl-C or kill "
                    + ProcessHandle.current().pid() + " (SIGTERM)");
        }
    }

    private static void checkpoint(WorldServer server, String file, PrintStream out) {
        try {
            Path written = (file.isEmpty() ? server.checkpoint() : server.checkpoint(Path.of(file)))
                    .get(30, java.util.concurrent.TimeUnit.SECONDS);
            out.println("checkpoint written to " + written);
        } catch (IllegalStateException e) {
            out.println(e.getMessage() + " (checkpoint FILE)");
        } catch (java.util.concurrent.ExecutionException e) {
            out.println("checkpoint failed: " + e.getCause().getMessage());
        } catch (java.util.concurrent.TimeoutException e) {
            out.println("checkpoint not written after 30 s");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The page's address as a person types it: every interface's server is reached on this machine's loopback. */
    static String pageAddress(String bind, int port) {
        String host = bind.equals("0.0.0.0") || bind.equals("::") ? "localhost"
                : bind.contains(":") ? "[" + bind + "]" : bind;
        return "http://" + host + ":" + port + "/";
    }

    static void printRanking(List<Score> ranking, PrintStream out) {
        out.println("Game over. Ranking:");
        int place = 1;
        for (Score score : ranking) {
            out.printf(Locale.ROOT, "%3d. %-16s %4d points  %3d fruit%n", place++, score.agent(), score.points(),
                    score.fruit());
        }
    }
}
