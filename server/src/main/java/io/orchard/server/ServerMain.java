package io.orchard.server;

import io.orchard.protocol.cli.Options;
import io.orchard.protocol.cli.UsageException;
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
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * The world server's command line: {@code ./orchard server [options]}. It prints the game's state
 * once a second and the ranking at the end, and reads commands from its console: {@code start},
 * {@code pause}, {@code continue}, {@code status}, {@code checkpoint [FILE]}, {@code stop}.
 */
public final class ServerMain {

    static final Options OPTIONS = new Options("orchard server",
            "Runs the Orchard world server: the world, the game and the protocol on one TCP port.")
            .value("port", "N", "TCP port; 0 picks a free one", String.valueOf(WorldServer.DEFAULT_PORT))
            .value("bind", "ADDRESS", "address to listen on; 0.0.0.0 for every interface", "127.0.0.1")
            .value("seed", "N", "seed of the world; drawn and printed when absent", null)
            .value("clock", "MODE", "realtime, or lockstep (a tick ends when every agent has ended its turn)",
                    "realtime")
            .value("tick-rate", "N", "ticks per simulated second", "20")
            .value("wait-for", "N", "start the game when N agents have registered (0: at the first)", "0")
            .value("time-limit", "SECONDS", "length of the game in simulated seconds", "300")
            .value("scenario", "FILE", "load the world from a scenario file instead of generating it", null)
            .value("write-scenario", "FILE", "write the world (generated from --seed) as a scenario file and exit",
                    null)
            .value("record", "FILE", "record every message accepted and sent, as newline-delimited JSON", null)
            .value("token", "SECRET", "require clients to present this token in their hello", null)
            .value("checkpoint", "FILE", "save the whole game to FILE: when fruit is collected, at the end, on the "
                    + "console's checkpoint command and every --checkpoint-every seconds", null)
            .value("checkpoint-every", "SECONDS", "with --checkpoint, also save every SECONDS of wall-clock time; "
                    + "0 for never", "60")
            .value("resume", "FILE", "continue the game saved in a checkpoint FILE (its world, seed, clock, scores; its "
                    + "agents wait for their controllers' resume tokens)", null)
            .flag("quiet", "do not print the status line every second");

    private ServerMain() {}

    /** The help text of the server's command line. */
    public static String help() {
        return OPTIONS.help() + "\nConsole commands: start, pause, continue, status, checkpoint [FILE], stop.\n";
    }

    /** Runs the server with the command line {@code args} (see {@link #help()}) and exits with its status. */
    public static void main(String[] args) throws Exception {
        System.exit(run(Arrays.asList(args), System.in, System.out, System.err));
    }

    /** Runs the command line; returns the process exit code. */
    public static int run(List<String> args, InputStream console, PrintStream out, PrintStream err) throws Exception {
        Options.Parsed options;
        WorldServer.Builder builder = WorldServer.builder();
        try {
            options = OPTIONS.parse(args);
            if (options.help()) {
                out.print(help());
                return 0;
            }
            configure(builder, options);
        } catch (UsageException | IllegalArgumentException e) {
            err.println("orchard server: " + e.getMessage());
            return 2;
        }
        if (options.has("write-scenario")) {
            Long given = options.longValue("seed", Long.MIN_VALUE, Long.MAX_VALUE);
            long seed = given != null ? given : java.util.concurrent.ThreadLocalRandom.current().nextLong(1, 1L << 48);
            Path file = Path.of(options.string("write-scenario"));
            ScenarioFile.write(WorldGenerator.standard(seed).generate().toScenario(), file);
            out.println("wrote the world of seed " + seed + " to " + file);
            return 0;
        }
        try (WorldServer server = builder.start()) {
            out.printf(Locale.ROOT, "Orchard server %s listening on port %d, seed %d, %s clock%n", Version.current(),
                    server.port(), server.seed(), options.has("resume") ? "the saved game's" : options.string("clock"));
            if (options.has("resume")) {
                out.println("resumed from " + options.string("resume") + ": " + server.status());
            }
            Thread commands = new Thread(() -> readCommands(server, console, out), "orchard-console");
            commands.setDaemon(true);
            commands.start();
            boolean quiet = options.has("quiet");
            while (!server.gameOver().isDone()) {
                try {
                    server.gameOver().get(1, java.util.concurrent.TimeUnit.SECONDS);
                } catch (java.util.concurrent.TimeoutException e) {
                    if (!quiet) {
                        out.println(server.status());
                    }
                } catch (java.util.concurrent.CancellationException e) {
                    break;
                }
            }
            if (server.gameOver().isDone() && !server.gameOver().isCancelled()) {
                printRanking(server.gameOver().join(), out);
            }
        } catch (IOException e) {
            err.println("orchard server: " + e.getMessage());
            return 1;
        }
        return 0;
    }

    private static void configure(WorldServer.Builder builder, Options.Parsed options) throws UsageException {
        builder.port(options.integer("port", 0, 65535)).bind(options.string("bind"))
                .clock(ClockMode.valueOf(options.choice("clock", "realtime", "lockstep").toUpperCase(Locale.ROOT)))
                .tickRate(options.integer("tick-rate", 1, 1000))
                .waitFor(options.integer("wait-for", 0, 10_000))
                .timeLimit(options.number("time-limit", 0.001, 1e7))
                .lockstepDeadline(Duration.ofSeconds(2));
        Long seed = options.longValue("seed", Long.MIN_VALUE, Long.MAX_VALUE);
        if (seed != null) {
            builder.seed(seed);
        }
        if (options.has("scenario")) {
            builder.scenario(Path.of(options.string("scenario")));
        }
        if (options.has("record")) {
            builder.record(Path.of(options.string("record")));
        }
        if (options.has("token")) {
            builder.token(options.string("token"));
        }
        double every = options.number("checkpoint-every", 0, 1e7);
        if (options.has("checkpoint")) {
            builder.checkpoint(Path.of(options.string("checkpoint")), every > 0 ? Duration.ofMillis((long) (every * 1000))
                    : null);
        }
        if (options.has("resume")) {
            builder.resume(Path.of(options.string("resume")));
        }
    }

    private static void readCommands(WorldServer server, InputStream console, PrintStream out) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(console, StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                String command = line.strip().toLowerCase(Locale.ROOT);
                if (command.startsWith("checkpoint")) {
                    checkpoint(server, line.strip().substring("checkpoint".length()).strip(), out);
                    continue;
                }
                switch (command) {
                    case "" -> { }
                    case "start" -> server.startGame();
                    case "pause", "continue", "resume" -> {
                        boolean paused = server.phase() == Phase.PAUSED;
                        if (command.equals("pause") == paused) {
                            out.println(paused ? "already paused" : "not paused");
                        } else {
                            server.togglePause();
                        }
                    }
                    case "status" -> out.println(server.status());
                    case "stop", "quit" -> server.endGame("stopped from the console");
                    default -> out.println("unknown command '" + command
                            + "'; commands: start, pause, continue, status, checkpoint [FILE], stop");
                }
            }
        } catch (IOException e) {
            // The console closed: the server goes on without it.
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

    static void printRanking(List<Score> ranking, PrintStream out) {
        out.println("Game over. Ranking:");
        int place = 1;
        for (Score score : ranking) {
            out.printf(Locale.ROOT, "%3d. %-16s %4d points  %3d fruit%n", place++, score.agent(), score.points(),
                    score.fruit());
        }
    }
}
