package io.orchard.cluster;

import io.orchard.cli.CommandLineErrors;
import io.orchard.cli.Decimal;
import io.orchard.cli.Seed;
import io.orchard.cli.Whole;
import io.orchard.protocol.value.ClockMode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.apache.pekko.actor.CoordinatedShutdown;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import picocli.CommandLine.TypeConversionException;

/**
 * The command line of a node of a cluster that serves one world: {@code orchard node}. It starts a
 * {@link ClusterNode} and prints the node's health and the parcels it hosts every few seconds, until
 * Ctrl-C or SIGTERM, when the node leaves the cluster (its parcels move to the other nodes).
 * {@link #command} hands it to a launcher as its subcommand {@code node}. Exit status: 0 done, 1
 * failed, 2 bad command line.
 */
@Command(name = "node", abbreviateSynopsis = true, sortOptions = false,
        description = {"Run a node of a cluster that serves one world (docs/scaling.md)", "",
            "Nodes started with the same seed and game settings, each given the cluster port of one or more "
                    + "nodes already up (--seed-nodes), serve one world: agents and viewers connect to any node's "
                    + "port with the protocol of one server. The first node is started without --seed-nodes, or "
                    + "with its own address."},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n", footerHeading = "%n",
        footer = {"It prints the node's health every 5 s: its cluster address, the members up, the game's phase "
                + "and tick, its clients, what it sent to other nodes and the parcels it hosts. Console commands, "
                + "for the game wherever its tick runs: start, pause, continue, status, checkpoint, stop. Ctrl-C "
                + "or SIGTERM leaves the cluster."})
public final class NodeMain implements Callable<Integer> {

    @Option(names = "--port", paramLabel = "N", defaultValue = "7557", converter = Port.class,
            description = "TCP port for agents and viewers; 0 picks a free one (default: ${DEFAULT-VALUE})")
    private int port;

    @Option(names = "--cluster-port", paramLabel = "N", defaultValue = "2551", converter = Port.class,
            description = "Port of the node's cluster member, for the other nodes (default: ${DEFAULT-VALUE})")
    private int clusterPort;

    @Option(names = "--seed-nodes", paramLabel = "HOST:PORT,...", split = ",", converter = SeedNode.class,
            description = "Cluster ports of nodes to join the cluster through; none: this node starts it")
    private List<String> seedNodes = new ArrayList<>();

    @Option(names = "--bind", paramLabel = "ADDRESS", defaultValue = "127.0.0.1",
            description = "Address to listen on, for clients and other nodes (default: ${DEFAULT-VALUE})")
    private String bind;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1998", converter = Seed.class,
            description = "The world's seed: the same on every node (default: ${DEFAULT-VALUE})")
    private long seed;

    @Option(names = "--clock", paramLabel = "MODE", defaultValue = "realtime", converter = Clock.class,
            description = "realtime or lockstep (default: ${DEFAULT-VALUE})")
    private ClockMode clock;

    @Option(names = "--tick-rate", paramLabel = "N", defaultValue = "20", converter = TickRate.class,
            description = "Ticks per simulated second (default: ${DEFAULT-VALUE})")
    private int tickRate;

    @Option(names = "--wait-for", paramLabel = "N", defaultValue = "0", converter = WaitFor.class,
            description = "Start the game when N agents have registered (default: at the first)")
    private int waitFor;

    @Option(names = "--time-limit", paramLabel = "SECONDS", defaultValue = "300", converter = TimeLimit.class,
            description = "The game's length in simulated seconds (default: ${DEFAULT-VALUE})")
    private double timeLimit;

    @Option(names = "--turn-deadline", paramLabel = "SECONDS", defaultValue = "2", converter = TurnDeadline.class,
            description = "In lockstep, how long a tick waits for an agent's turn (default: ${DEFAULT-VALUE})")
    private double turnDeadline;

    @Option(names = "--parcel-size", paramLabel = "UNITS", defaultValue = "60", converter = ParcelSize.class,
            description = "The side of the world's square parcels (default: ${DEFAULT-VALUE})")
    private double parcelSize;

    @Option(names = "--record", paramLabel = "FILE",
            description = "Record the game to FILE, on the node where the tick runs")
    private Path record;

    @Option(names = "--scenario", paramLabel = "FILE",
            description = "Load the world from a scenario file instead of generating it from --seed; every node "
                    + "of the cluster loads the same file")
    private Path scenario;

    @Option(names = "--checkpoint", paramLabel = "FILE",
            description = "Save the whole game to FILE, the same file for every node (one machine: a local path; "
                    + "several: a shared file system): when it starts, when fruit is collected, at the end, on the "
                    + "console's checkpoint command, every --checkpoint-every seconds and when the tick's node leaves. "
                    + "When a node is lost, the world goes back to it")
    private Path checkpoint;

    @Option(names = "--checkpoint-every", paramLabel = "SECONDS", defaultValue = "60", converter = Every.class,
            description = "With --checkpoint, also save every SECONDS of wall-clock time, the most play a lost "
                    + "node loses; 0 for never (default: ${DEFAULT-VALUE})")
    private double checkpointEvery;

    @Option(names = "--resume", paramLabel = "FILE",
            description = "Go on with the game saved in a checkpoint FILE of this seed (its agents wait for their "
                    + "controllers' resume tokens), instead of a new one")
    private Path resume;

    @Option(names = "--down-after", paramLabel = "SECONDS", defaultValue = "20", converter = DownAfter.class,
            description = "How long a node that stopped answering stays unreachable before the others take it for "
                    + "lost (default: ${DEFAULT-VALUE})")
    private double downAfter;

    @Option(names = "--token", paramLabel = "SECRET",
            description = "Require clients to present this token in their hello: the same on every node")
    private String token;

    @Option(names = "--operator-token", paramLabel = "SECRET", defaultValue = "${env:ORCHARD_OPERATOR_TOKEN}",
            description = "Let a client that presents this token in its hello, at any node, start, pause and resume "
                    + "the game (GameControl); without it only the nodes' consoles do. Also read from "
                    + "ORCHARD_OPERATOR_TOKEN")
    private String operatorToken;

    @Option(names = "--name-reservation", paramLabel = "SECONDS", defaultValue = "60", converter = Reservation.class,
            description = "How long a dropped agent's name and score stay its controller's: meanwhile only its "
                    + "resume token registers the name, at any node; 0 frees it at once (default: ${DEFAULT-VALUE})")
    private double nameReservation;

    @Option(names = "--quiet", description = "Do not print the node's health")
    private boolean quiet;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    @Spec
    private CommandSpec spec;

    private final InputStream console;
    private final PrintStream out;

    private NodeMain(InputStream console, PrintStream out) {
        this.console = console;
        this.out = out;
    }

    /** Runs a node with the command line {@code args} and exits with its status. */
    public static void main(String[] args) {
        System.exit(CommandLineErrors.execute(command(System.in, System.out, System.err)
                .setCommandName("orchard node"), List.of(args), System.err));
    }

    /**
     * The command line as a picocli command named {@code node}, reading console commands from
     * {@code console} and printing to {@code out} and {@code err}.
     */
    public static CommandLine command(InputStream console, PrintStream out, PrintStream err) {
        return new CommandLine(new NodeMain(console, out)).setOut(new PrintWriter(out, true))
                .setErr(new PrintWriter(err, true));
    }

    /** Runs the node as the options say, until the JVM is asked to end. */
    @Override
    public Integer call() throws Exception {
        ClusterNode.Builder builder = ClusterNode.builder();
        try {
            builder.bind(bind).port(port).clusterPort(clusterPort).seedNodes(seedNodes).seed(seed).clock(clock)
                    .tickRate(tickRate).waitFor(waitFor).timeLimit(timeLimit).parcelSize(parcelSize)
                    .lockstepDeadline(Duration.ofNanos((long) (turnDeadline * 1e9))).token(token)
                    .operatorToken(operatorToken).nameReservation(Duration.ofMillis((long) (nameReservation * 1000)))
                    .downAfter(Duration.ofMillis((long) (downAfter * 1000)));
            if (checkpoint != null) {
                builder.checkpoint(checkpoint, checkpointEvery > 0 ? Duration.ofMillis((long) (checkpointEvery * 1000))
                        : null);
            }
            if (resume != null) {
                builder.resume(resume);
            }
            if (record != null) {
                builder.record(record);
            }
            if (scenario != null) {
                builder.scenario(scenario);
            }
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage(), e);
        }
        ClusterNode node = builder.start();
        CountDownLatch ended = new CountDownLatch(1);
        // Pekko's remoting closes its transport in a JVM shutdown hook of its own, at once unless hooks
        // registered with its coordinated shutdown are still running: a plain JVM hook would leave the
        // cluster without a transport, and the others would take the node for lost.
        CoordinatedShutdown.get(node.system()).addJvmShutdownHook(() -> {
            out.println("leaving the cluster");
            node.close();
            ended.countDown();
        });
        out.printf(Locale.ROOT, "node listening for agents and viewers on %s:%d, cluster member at port %d%n", bind,
                node.port(), node.clusterPort());
        Thread commands = new Thread(() -> readCommands(node), "orchard-node-console");
        commands.setDaemon(true);
        commands.start();
        while (!ended.await(5, java.util.concurrent.TimeUnit.SECONDS)) {
            if (!quiet) {
                out.println(node.status());
            }
        }
        return 0;
    }

    /** The console's commands, for the game wherever its tick runs. */
    private void readCommands(ClusterNode node) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(console, StandardCharsets.UTF_8))) {
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                switch (line.strip().toLowerCase(Locale.ROOT)) {
                    case "" -> { }
                    case "start" -> node.startGame();
                    case "pause" -> node.pauseGame();
                    case "continue", "resume" -> node.resumeGame();
                    case "status" -> out.println(node.status());
                    case "checkpoint" -> {
                        node.checkpoint();
                        out.println(checkpoint == null ? "no checkpoint file: start the nodes with --checkpoint FILE"
                                : "the game is saved to " + checkpoint + " at the end of the tick");
                    }
                    case "stop", "quit" -> node.endGame("stopped from a node's console");
                    default -> out.println("unknown command '" + line.strip()
                            + "'; commands: start, pause, continue, status, checkpoint, stop");
                }
            }
        } catch (IOException e) {
            // Unreadable input is closed input.
        }
        out.println("console input closed: the node runs on without its console; stop it with Ctrl-C or kill "
                + ProcessHandle.current().pid() + " (SIGTERM)");
    }

    static final class Every extends Decimal {
        Every() {
            super(0, 1e7, "0-10000000 seconds; 0 for never");
        }
    }

    static final class DownAfter extends Decimal {
        DownAfter() {
            super(1, 3600, "1-3600 seconds");
        }
    }

    static final class Reservation extends Decimal {
        Reservation() {
            super(0, 1e7, "0-10000000 seconds; 0 frees a dropped agent's name at once");
        }
    }

    /** A port to listen on, 0 for any free one. */
    static final class Port extends Whole {
        Port() {
            super(0, 65535, "a port 0-65535");
        }
    }

    static final class TickRate extends Whole {
        TickRate() {
            super(1, 1000, "1-1000 ticks per simulated second");
        }
    }

    static final class WaitFor extends Whole {
        WaitFor() {
            super(0, 100_000, "0-100000 agents");
        }
    }

    static final class TimeLimit extends Decimal {
        TimeLimit() {
            super(0.001, 1e7, "0.001-10000000 simulated seconds");
        }
    }

    static final class TurnDeadline extends Decimal {
        TurnDeadline() {
            super(0.001, 3600, "0.001-3600 seconds");
        }
    }

    static final class ParcelSize extends Decimal {
        ParcelSize() {
            super(1, 10_000, "1-10000 units");
        }
    }

    /** A node to join through: host:port. */
    static final class SeedNode implements ITypeConverter<String> {
        @Override
        public String convert(String text) {
            String node = text.strip();
            int colon = node.lastIndexOf(':');
            if (colon <= 0 || !node.substring(colon + 1).matches("\\d{1,5}")
                    || Integer.parseInt(node.substring(colon + 1)) > 65535) {
                throw new TypeConversionException("'" + text + "' is not a node (expected host:port, the port "
                        + "1-65535 of a node's cluster member)");
            }
            return node;
        }
    }

    /** realtime or lockstep, in any case. */
    static final class Clock implements ITypeConverter<ClockMode> {
        @Override
        public ClockMode convert(String text) {
            try {
                return ClockMode.valueOf(text.strip().toUpperCase(Locale.ROOT));
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException("'" + text + "' is not a clock (expected realtime or lockstep)");
            }
        }
    }
}
