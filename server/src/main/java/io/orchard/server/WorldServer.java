package io.orchard.server;

import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Score;
import io.orchard.server.net.NetLimits;
import io.orchard.server.net.NetServer;
import io.orchard.server.sim.GameListener;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.Placement;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.sim.TickLoop;
import io.orchard.server.sim.TickStats;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.OptionalInt;
import java.util.concurrent.CompletableFuture;
import java.util.stream.Collectors;

/**
 * An Orchard world server that any JVM program can embed: it holds the world, runs the game and
 * speaks the protocol to agents and viewers over TCP.
 *
 * <pre>{@code
 * try (WorldServer server = WorldServer.builder().port(0).seed(1998).clock(ClockMode.LOCKSTEP)
 *         .listener(new GameListener() {
 *             public void gameOver(String reason, List<Score> ranking) { System.out.println(ranking); }
 *         })
 *         .start()) {
 *     int port = server.port(); // connect agents here
 *     server.awaitGameOver();
 * }
 * }</pre>
 *
 * <p>{@link #close()} stops the game and the network and leaves no thread behind.
 */
public final class WorldServer implements AutoCloseable {

    /** The port the server listens on unless told otherwise. */
    public static final int DEFAULT_PORT = 7557;

    private final Simulation simulation;
    private final NetServer net;
    private final TickLoop loop;
    private final Thread tickThread;
    private final Recorder recorder;
    private final GameResults gameOver;
    private final Checkpoints checkpoints;
    private final WebFrontEnd.Serving web;
    private boolean closed;

    WorldServer(Simulation simulation, NetServer net, TickLoop loop, Thread tickThread, Recorder recorder,
                GameResults gameOver, Checkpoints checkpoints, WebFrontEnd.Serving web) {
        this.simulation = simulation;
        this.net = net;
        this.loop = loop;
        this.tickThread = tickThread;
        this.recorder = recorder;
        this.gameOver = gameOver;
        this.checkpoints = checkpoints;
        this.web = web;
    }

    /** A builder with the defaults: port 7557 on loopback, a random seed, realtime at 20 ticks/s. */
    public static Builder builder() {
        return new Builder();
    }

    /** The port the server listens on (the real one when built with port 0). */
    public int port() {
        return net.port();
    }

    /** The address and port the server listens on. */
    public InetSocketAddress address() {
        return net.address();
    }

    /**
     * The port the browser viewer's page is served on, when the server was built with
     * {@link Builder#httpPort(int)}; empty otherwise.
     */
    public OptionalInt httpPort() {
        return web == null ? OptionalInt.empty() : OptionalInt.of(web.address().getPort());
    }

    /** The seed the world was made from. */
    public long seed() {
        return simulation.seed();
    }

    /** Starts the game now without waiting for more agents. Safe from any thread. */
    public void startGame() {
        simulation.execute(simulation::start);
    }

    /** Pauses a running game, or continues a paused one. Safe from any thread. */
    public void togglePause() {
        simulation.execute(simulation::togglePause);
    }

    /**
     * Pauses the game if it runs, after what was asked before ({@link #startGame()} included). Safe
     * from any thread.
     */
    public void pauseGame() {
        simulation.execute(() -> {
            if (simulation.phase() == Phase.RUNNING) {
                simulation.togglePause();
            }
        });
    }

    /** Continues the game if it is paused, after what was asked before. Safe from any thread. */
    public void resumeGame() {
        simulation.execute(() -> {
            if (simulation.phase() == Phase.PAUSED) {
                simulation.togglePause();
            }
        });
    }

    /** Ends the game now. Safe from any thread. */
    public void endGame(String reason) {
        simulation.execute(() -> simulation.end(reason));
    }

    /**
     * Ends the game, if it is not over, and starts a new one of the world of {@code seed} on the same
     * server and connections, as the operator's {@code GameControl restart} does: at the end of the
     * current tick, or at once while no tick runs. Returns once it is done: {@link #gameOver()} is
     * then the new game's. Safe from any thread but the game's own (a {@link GameListener}'s).
     *
     * @throws IllegalStateException when this server plays one game only: it records its game, saves
     *                               it to a checkpoint file, or continues a saved one
     */
    public void restart(long seed) {
        CompletableFuture<Void> done = new CompletableFuture<>();
        simulation.execute(() -> {
            try {
                simulation.restart(seed, () -> done.complete(null));
            } catch (IllegalStateException e) {
                done.completeExceptionally(e);
            }
        });
        // A lockstep tick under way ends when its agents have ended their turns, or at its deadline.
        long waitMillis = simulation.config().lockstepDeadline().toMillis() + 5_000;
        try {
            done.get(waitMillis, java.util.concurrent.TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (java.util.concurrent.ExecutionException e) {
            throw (IllegalStateException) e.getCause();
        } catch (java.util.concurrent.TimeoutException e) {
            throw new IllegalStateException("the game did not restart within " + waitMillis + " ms", e);
        }
    }

    /** A one-line account of the game: phase, time, agents, fruit left and scores. Safe from any thread. */
    public String status() {
        CompletableFuture<String> status = new CompletableFuture<>();
        simulation.execute(() -> status.complete(String.format(java.util.Locale.ROOT,
                "%s  t=%.1fs  tick %d  agents %s%s  fruit left %d  scores %s",
                simulation.phase().name().toLowerCase(java.util.Locale.ROOT), simulation.time(), simulation.tick(),
                simulation.agentNames(), simulation.waitingAgents().isEmpty() ? ""
                        : "  waiting to be resumed " + simulation.waitingAgents(),
                simulation.fruitLeft(), scores(simulation.ranking()))));
        try {
            return status.get(5, java.util.concurrent.TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
            return "status unavailable: " + e;
        }
    }

    /** The ranking as the status line shows it: "FirstAgent 2 points (1 fruit), Dwarf 0 points (0 fruit)". */
    static String scores(List<Score> ranking) {
        if (ranking.isEmpty()) {
            return "none";
        }
        return ranking.stream().map(score -> score.agent() + " " + score.points()
                + (score.points() == 1 ? " point" : " points") + " (" + score.fruit() + " fruit)")
                .collect(Collectors.joining(", "));
    }

    /**
     * How long the simulation's thread worked per tick since the start or the last
     * {@link #resetTickStats()}: median, 99th percentile and maximum. Safe from any thread.
     */
    public TickStats tickStats() {
        return loop.stats();
    }

    /** Starts measuring tick times afresh (to leave out a warm-up, for example). Safe from any thread. */
    public void resetTickStats() {
        loop.resetStats();
    }

    /**
     * Writes the whole game to the checkpoint file the server was built with, at the end of the
     * current tick. Safe from any thread.
     *
     * @return completes with the file once it is written, or exceptionally with what went wrong
     * @throws IllegalStateException when the server was built without a checkpoint file
     */
    public CompletableFuture<Path> checkpoint() {
        if (checkpoints.file() == null) {
            throw new IllegalStateException("this server has no checkpoint file: start it with one, or name a file");
        }
        return checkpoint(checkpoints.file());
    }

    /**
     * Writes the whole game to {@code file} at the end of the current tick, atomically (a crash
     * leaves the old file or the new one). Safe from any thread.
     *
     * @return completes with the file once it is written, or exceptionally with what went wrong
     */
    public CompletableFuture<Path> checkpoint(Path file) {
        Objects.requireNonNull(file, "checkpoint file");
        CompletableFuture<Path> written = new CompletableFuture<>();
        simulation.checkpointAtTickEnd(state -> checkpoints.write(state, file, written));
        return written;
    }

    /** The phase of the game. */
    public Phase phase() {
        return simulation.phase();
    }

    /**
     * Completes with the final ranking when the current game is over; after a {@link #restart}, the
     * new game's.
     */
    public CompletableFuture<List<Score>> gameOver() {
        return gameOver.current();
    }

    /** Waits until the current game is over and returns the ranking. */
    public List<Score> awaitGameOver() throws InterruptedException {
        try {
            return gameOver.current().get();
        } catch (java.util.concurrent.ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        }
    }

    /** Whether {@link #close()} was called. */
    synchronized boolean closed() {
        return closed;
    }

    /**
     * Stops the game and the network, waits for the checkpoint being written (if any) and every
     * thread to end, and closes the recording. Closing again does nothing; a second caller waits
     * until the first is done.
     */
    @Override
    public synchronized void close() {
        if (closed) {
            return;
        }
        closed = true;
        // The clock stops first, so that nothing the closing connections cause reaches the game.
        loop.stop();
        try {
            tickThread.join(5_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        checkpoints.close();
        if (web != null) {
            web.close();
        }
        net.close();
        simulation.stopped();
        recorder.close();
        gameOver.cancel();
    }

    /**
     * Configures a {@link WorldServer}. Every setter checks its value at once and names it when it is
     * wrong.
     */
    public static final class Builder {

        // The settings, read by Startup when it puts the server together.
        String bind = "127.0.0.1";
        int port = DEFAULT_PORT;
        Integer httpPort;
        Long seed;
        ClockMode clock = ClockMode.REALTIME;
        int tickRate = SimulationConfig.DEFAULT.tickRate();
        double timeLimit = SimulationConfig.DEFAULT.timeLimit();
        int waitFor;
        Duration lockstepDeadline = SimulationConfig.DEFAULT.lockstepDeadline();
        Path scenario;
        Path record;
        Path checkpointFile;
        Duration checkpointEvery;
        Path resume;
        Duration nameReservation = Duration.ofSeconds(60);
        String token;
        String operatorToken;
        NetLimits limits = NetLimits.DEFAULT;
        Placement placement = (name, radius) -> null;
        String oneGame;
        final List<GameListener> listeners = new ArrayList<>();

        private Builder() {}

        /** The address to listen on: loopback by default; "0.0.0.0" for every interface. */
        public Builder bind(String address) {
            this.bind = Objects.requireNonNull(address, "bind address");
            return this;
        }

        /** The TCP port, 0 for any free one. */
        public Builder port(int port) {
            this.port = OptionChecks.port(port, "port");
            return this;
        }

        /**
         * Also serve the browser viewer, a page at {@code http://host:port/} whose script watches the
         * game and instructs its agents over a WebSocket, on this port of the same address (0 for any
         * free one; see {@link WorldServer#httpPort()}). Off unless asked; it needs the web module
         * ({@code io.orchard:web}) on the class path, and {@link #start()} says so when it is missing.
         */
        public Builder httpPort(int port) {
            this.httpPort = OptionChecks.port(port, "HTTP port");
            return this;
        }

        /** The seed the world is made from; without one a seed is drawn (and {@link #seed()} tells it). */
        public Builder seed(long seed) {
            this.seed = seed;
            return this;
        }

        /** Realtime or lockstep. */
        public Builder clock(ClockMode clock) {
            this.clock = Objects.requireNonNull(clock, "clock");
            return this;
        }

        /** Ticks per simulated second, 1 to 1000. */
        public Builder tickRate(int tickRate) {
            this.tickRate = OptionChecks.tickRate(tickRate);
            return this;
        }

        /** The game's length in simulated seconds. */
        public Builder timeLimit(double seconds) {
            this.timeLimit = OptionChecks.timeLimit(seconds);
            return this;
        }

        /** Start the game only when this many agents have registered (0: at the first). */
        public Builder waitFor(int agents) {
            this.waitFor = OptionChecks.waitFor(agents);
            return this;
        }

        /**
         * In lockstep, how long (wall clock) a tick waits for agents that have not ended their turn,
         * and a game whose agents have come waits for their setup turns; 2 s by default. A client
         * that misses it three turns in a row is no longer waited for until it ends a turn in time
         * again. Every missed turn is recorded.
         */
        public Builder lockstepDeadline(Duration deadline) {
            this.lockstepDeadline = OptionChecks.lockstepDeadline(deadline);
            return this;
        }

        /** Load the world from a scenario file instead of generating it. */
        public Builder scenario(Path file) {
            this.scenario = Objects.requireNonNull(file, "scenario file");
            return this;
        }

        /** Record every message accepted and sent to this file (newline-delimited JSON). */
        public Builder record(Path file) {
            this.record = Objects.requireNonNull(file, "record file");
            return this;
        }

        /**
         * Save the whole game to {@code file} after every tick in which a fruit was collected, when
         * the game ends, on {@link WorldServer#checkpoint()} and, unless {@code every} is null,
         * every {@code every} of wall-clock time. Each write is atomic.
         */
        public Builder checkpoint(Path file, Duration every) {
            this.checkpointFile = Objects.requireNonNull(file, "checkpoint file");
            this.checkpointEvery = OptionChecks.checkpointInterval(every);
            return this;
        }

        /**
         * Continue the game saved in a checkpoint file instead of starting a new one: its world, seed,
         * clock, scores and agents (which wait for their controllers to register them again with their
         * resume tokens). The seed, clock, tick rate, time limit, wait-for count and scenario set on
         * this builder are replaced by the checkpoint's; a recording is continued, not replaced.
         */
        public Builder resume(Path file) {
            this.resume = Objects.requireNonNull(file, "checkpoint file to resume");
            return this;
        }

        /**
         * How long the name and score of an agent whose connection dropped stay its controller's
         * (default 60 s): meanwhile whoever else registers the name gets {@code name_in_use}, saying
         * when it frees up, and the controller gets the agent back with its resume token. Zero frees
         * the name at once.
         */
        public Builder nameReservation(Duration time) {
            this.nameReservation = OptionChecks.nameReservation(time);
            return this;
        }

        /**
         * Require clients to present this shared secret in their hello. It admits a client, and
         * nothing more: controlling the game takes the {@link #operatorToken operator token}.
         */
        public Builder token(String token) {
            this.token = OptionChecks.token(token, operatorToken);
            return this;
        }

        /**
         * Let a client that presents this secret in its hello (protocol version 2) start, pause and
         * resume the game with {@code GameControl}, as the console and {@link WorldServer#startGame()}
         * and {@link WorldServer#togglePause()} do. Without one (the default) no client controls the
         * game; every other client's {@code GameControl} is refused with {@code forbidden}. It must
         * differ from the {@link #token token}, which every client holds.
         */
        public Builder operatorToken(String operatorToken) {
            this.operatorToken = OptionChecks.operatorToken(operatorToken, token);
            return this;
        }

        /**
         * Refuse to restart the game ({@link WorldServer#restart}, the operator's {@code GameControl
         * restart}), with this reason: for a program that ends with the server's first game. A server
         * that records its game, saves it to a checkpoint file or continues a saved one refuses
         * restarts anyway.
         */
        public Builder oneGame(String reason) {
            if (reason == null || reason.isBlank()) {
                throw new IllegalArgumentException("the reason for playing one game only must be said, was "
                        + (reason == null ? "null" : "'" + reason + "'"));
            }
            this.oneGame = reason;
            return this;
        }

        /** Per-connection limits (rates, timeouts, queues). */
        public Builder limits(NetLimits limits) {
            this.limits = Objects.requireNonNull(limits, "limits");
            return this;
        }

        /** Choose where agents stand when they register (by default the seed draws free places). */
        public Builder placement(Placement placement) {
            this.placement = Objects.requireNonNull(placement, "placement");
            return this;
        }

        /** Hear what happens in the game (on the simulation's thread). */
        public Builder listener(GameListener listener) {
            listeners.add(Objects.requireNonNull(listener, "listener"));
            return this;
        }

        /**
         * Builds the world, binds the port and starts the clock.
         *
         * @throws IOException when the scenario cannot be read, the recording cannot be written or the
         *                     port cannot be bound
         */
        public WorldServer start() throws IOException {
            return Startup.start(this);
        }
    }
}
