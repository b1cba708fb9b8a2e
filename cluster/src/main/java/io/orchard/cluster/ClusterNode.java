package io.orchard.cluster;

import io.orchard.cluster.game.SplitGame;
import io.orchard.cluster.node.Gateway;
import io.orchard.cluster.node.GatewayCommand;
import io.orchard.cluster.node.NodeSettings;
import io.orchard.cluster.node.ParcelEntity;
import io.orchard.cluster.node.ShardedParcels;
import io.orchard.cluster.node.TickCommand;
import io.orchard.cluster.node.TickGames;
import io.orchard.cluster.node.TickSingleton;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.cluster.parcel.ParcelId;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.OptionChecks;
import io.orchard.server.Version;
import io.orchard.server.net.NetLimits;
import io.orchard.server.net.NetServer;
import io.orchard.server.sim.BodyLimits;
import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.CheckpointFile;
import io.orchard.server.sim.FileRecorder;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import io.orchard.server.world.scenario.Scenario;
import io.orchard.server.world.scenario.ScenarioFile;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongFunction;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.ActorRefResolver;
import org.apache.pekko.actor.typed.ActorSystem;
import org.apache.pekko.actor.typed.Props;
import org.apache.pekko.actor.typed.javadsl.AskPattern;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.apache.pekko.actor.typed.receptionist.Receptionist;
import org.apache.pekko.cluster.sharding.ShardRegion.CurrentShardRegionState;
import org.apache.pekko.cluster.sharding.typed.ClusterShardingQuery;
import org.apache.pekko.cluster.sharding.typed.GetShardRegionState;
import org.apache.pekko.cluster.sharding.typed.javadsl.ClusterSharding;
import org.apache.pekko.cluster.typed.Cluster;
import org.apache.pekko.cluster.typed.ClusterSingleton;
import org.apache.pekko.cluster.typed.Join;
import org.apache.pekko.cluster.typed.SingletonActor;

/**
 * A node of a cluster that serves one world: a member of a Pekko cluster (found through its seed
 * nodes), hosting some of the world's parcels as sharded entities, perhaps the tick (a cluster
 * singleton, on the oldest node), and a gateway where agents and viewers connect with the same
 * protocol as to one server. Every node of a cluster is started with the same world (seed) and game
 * settings. See docs/scaling.md.
 *
 * <pre>{@code
 * try (ClusterNode node = ClusterNode.builder().port(7557).clusterPort(2551)
 *         .seedNodes(List.of("127.0.0.1:2551")).seed(1998).clock(ClockMode.LOCKSTEP).start()) {
 *     // agents connect to 127.0.0.1:7557, or to any other node's port
 * }
 * }</pre>
 */
public final class ClusterNode implements AutoCloseable {

    private final ActorSystem<Void> system;
    private final NetServer net;
    private final Gateway gateway;
    private final ActorRef<TickCommand> tick;
    private final AtomicLong takenUp;

    private ClusterNode(ActorSystem<Void> system, NetServer net, Gateway gateway, ActorRef<TickCommand> tick,
                        AtomicLong takenUp) {
        this.system = system;
        this.net = net;
        this.gateway = gateway;
        this.tick = tick;
        this.takenUp = takenUp;
    }

    /**
     * How many parcels with agents of their own the tick, while on this node, kept for a node that
     * left and gave back to them as they started on another.
     */
    public long parcelsTakenUp() {
        return takenUp.get();
    }

    /** Saves the game to the cluster-wide checkpoint file at the end of the tick under way, if there is one. */
    public void checkpoint() {
        tick.tell(new TickCommand.Control(TickCommand.Command.CHECKPOINT, null));
    }

    /** A builder with the defaults: port 7557 and cluster port 2551 on loopback, realtime, parcels of 60. */
    public static Builder builder() {
        return new Builder();
    }

    /** The port agents and viewers connect to. */
    public int port() {
        return net.port();
    }

    /** The port the node's cluster member listens on, for other nodes. */
    public int clusterPort() {
        return Cluster.get(system).selfMember().address().getPort().orElseThrow();
    }

    /** How many members of the cluster are up, as this node sees it. */
    public long membersUp() {
        long up = 0;
        for (org.apache.pekko.cluster.Member member : Cluster.get(system).state().getMembers()) {
            if (member.status() == org.apache.pekko.cluster.MemberStatus.up()) {
                up++;
            }
        }
        return up;
    }

    /** The parcels this node hosts now, row by row. */
    public List<ParcelId> parcelsHere() {
        try {
            CurrentShardRegionState state = AskPattern.<ClusterShardingQuery, CurrentShardRegionState>ask(
                    ClusterSharding.get(system).shardState(),
                    replyTo -> new GetShardRegionState(ParcelEntity.TYPE, replyTo), Duration.ofSeconds(5),
                    system.scheduler()).toCompletableFuture().get(10, TimeUnit.SECONDS);
            List<ParcelId> here = new ArrayList<>();
            state.getShards().forEach(shard -> shard.getEntityIds().forEach(id -> here.add(ParcelId.parse(id))));
            here.sort(null);
            return here;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return List.of();
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
            return List.of();
        }
    }

    /**
     * A line on the node's health: its cluster address, the members up, the game's tick and phase as
     * the tick last told this node, its clients, what it sent to other nodes and the parcels it hosts.
     */
    public String status() {
        List<ParcelId> parcels = parcelsHere();
        long[] sent = io.orchard.cluster.node.ClusterSerializer.sent();
        return String.format(java.util.Locale.ROOT, "node %s  members up %d  %s  tick %d  clients %d  sent %d "
                        + "messages, %d bytes to other nodes  parcels %d %s",
                Cluster.get(system).selfMember().address().hostPort(), membersUp(),
                gateway.phase().wireName(), gateway.tick(), gateway.clients(), sent[0], sent[1], parcels.size(),
                parcels.stream().map(ParcelId::toString).toList());
    }

    /** Starts the game now without waiting for more agents, wherever the tick runs. Safe from any thread. */
    public void startGame() {
        tick.tell(new TickCommand.Control(TickCommand.Command.START, null));
    }

    /** Pauses the game if it runs. Safe from any thread. */
    public void pauseGame() {
        tick.tell(new TickCommand.Control(TickCommand.Command.PAUSE, null));
    }

    /** Continues the game if it is paused. Safe from any thread. */
    public void resumeGame() {
        tick.tell(new TickCommand.Control(TickCommand.Command.RESUME, null));
    }

    /** Ends the game now, for this reason. Safe from any thread. */
    public void endGame(String reason) {
        tick.tell(new TickCommand.Control(TickCommand.Command.END, Objects.requireNonNull(reason, "reason")));
    }

    /** The node's actor system, for programs that look into the cluster. */
    public ActorSystem<Void> system() {
        return system;
    }

    /** Leaves the cluster, closes the gateway and stops the node's actors. */
    @Override
    public void close() {
        net.close();
        system.terminate();
        try {
            system.getWhenTerminated().toCompletableFuture().get(60, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
            throw new IllegalStateException("the node did not stop within 60 s", e);
        }
    }

    /**
     * Configures a {@link ClusterNode}; every setter checks its value and names it when it is wrong, the
     * options a server also takes with the server's own checks, so that they are refused in its words.
     */
    public static final class Builder {

        private String bind = "127.0.0.1";
        private int port = 7557;
        private int clusterPort = 2551;
        private List<String> seedNodes = List.of();
        private long seed = 1998;
        private ClockMode clock = ClockMode.REALTIME;
        private int tickRate = SimulationConfig.DEFAULT.tickRate();
        private double timeLimit = SimulationConfig.DEFAULT.timeLimit();
        private int waitFor;
        private Duration lockstepDeadline = SimulationConfig.DEFAULT.lockstepDeadline();
        private double parcelSize = 60;
        private Path record;
        private Path scenario;
        private String token;
        private String operatorToken;
        private Duration nameReservation = Duration.ofSeconds(60);
        private Path checkpoint;
        private Duration checkpointEvery;
        private Path resume;
        private Duration downAfter = Duration.ofSeconds(20);

        private Builder() {}

        /** The address the gateway and the cluster member listen on; loopback by default. */
        public Builder bind(String address) {
            this.bind = Objects.requireNonNull(address, "bind address");
            return this;
        }

        /** The port agents and viewers connect to, 0 for any free one. */
        public Builder port(int port) {
            this.port = OptionChecks.port(port, "port");
            return this;
        }

        /** The port of the node's cluster member, 0 for any free one. */
        public Builder clusterPort(int port) {
            this.clusterPort = OptionChecks.port(port, "cluster port");
            return this;
        }

        /**
         * The nodes to join the cluster through, {@code host:port} each (their cluster ports); none
         * (the default): this node starts a cluster of its own, which others join through it.
         */
        public Builder seedNodes(List<String> nodes) {
            for (String node : nodes) {
                int colon = node.lastIndexOf(':');
                if (colon <= 0 || !node.substring(colon + 1).matches("\\d{1,5}")) {
                    throw new IllegalArgumentException("a seed node is host:port, was '" + node + "'");
                }
            }
            this.seedNodes = List.copyOf(nodes);
            return this;
        }

        /** The seed the world is made from: the same on every node. */
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

        /** Start the game only when this many agents have registered (0: at the first). */
        public Builder waitFor(int agents) {
            this.waitFor = OptionChecks.waitFor(agents);
            return this;
        }

        /** The game's length in simulated seconds. */
        public Builder timeLimit(double seconds) {
            this.timeLimit = OptionChecks.timeLimit(seconds);
            return this;
        }

        /** In lockstep, how long a tick waits for agents that have not ended their turn. */
        public Builder lockstepDeadline(Duration deadline) {
            this.lockstepDeadline = OptionChecks.lockstepDeadline(deadline);
            return this;
        }

        /** The side of the world's parcels in units. */
        public Builder parcelSize(double size) {
            if (!(size > 0) || Double.isInfinite(size)) {
                throw new IllegalArgumentException("parcel size must be a positive number of units, was " + size);
            }
            this.parcelSize = size;
            return this;
        }

        /**
         * Load the world from a scenario file instead of generating it from the seed, as a server's
         * {@code scenario}: every node of the cluster loads the same file.
         */
        public Builder scenario(Path file) {
            this.scenario = Objects.requireNonNull(file, "scenario file");
            return this;
        }

        /** Record the game to this file, on the node where the tick runs. */
        public Builder record(Path file) {
            this.record = Objects.requireNonNull(file, "record file");
            return this;
        }

        /** Require clients to present this shared secret in their hello, as a server's {@code token}. */
        public Builder token(String token) {
            this.token = OptionChecks.token(token, operatorToken);
            return this;
        }

        /**
         * Let a client that presents this secret in its hello start, pause and resume the game with
         * {@code GameControl}, at any node; without one no client controls the game. It must differ
         * from the {@link #token token}.
         */
        public Builder operatorToken(String operatorToken) {
            this.operatorToken = OptionChecks.operatorToken(operatorToken, token);
            return this;
        }

        /**
         * How long the name and score of an agent whose connection dropped stay its controller's
         * (default 60 s), as on one server; zero frees the name at once.
         */
        public Builder nameReservation(Duration time) {
            this.nameReservation = OptionChecks.nameReservation(time);
            return this;
        }

        /**
         * Save the whole game to {@code file}, a file every node reaches (on one machine, a local
         * path; on several, a shared file system), the same on every node: when the game starts,
         * after every tick in which fruit was collected, when it ends, when the tick leaves a node,
         * and, unless {@code every} is null, every {@code every} of wall-clock time. When a node is
         * lost, the world rolls back to it. Each write is atomic.
         */
        public Builder checkpoint(Path file, Duration every) {
            this.checkpoint = Objects.requireNonNull(file, "checkpoint file");
            this.checkpointEvery = OptionChecks.checkpointInterval(every);
            return this;
        }

        /**
         * Go on with the game saved in a checkpoint file (of this node's seed) instead of starting a
         * new one, as a server's {@code --resume}: its agents wait for their controllers.
         */
        public Builder resume(Path file) {
            this.resume = Objects.requireNonNull(file, "checkpoint file to resume");
            return this;
        }

        /**
         * How long a node that stopped answering stays unreachable before the others take it for
         * lost (20 s by default): too short, and a node busy for a moment is lost too.
         */
        public Builder downAfter(Duration time) {
            if (time == null || time.isNegative() || time.isZero()) {
                throw new IllegalArgumentException("down-after must be positive, was " + time);
            }
            this.downAfter = time;
            return this;
        }

        /**
         * Joins the cluster (or starts one), hosts parcels and the tick's singleton, and opens the
         * gateway.
         *
         * @throws IOException when the gateway's port cannot be bound
         */
        public ClusterNode start() throws IOException {
            SimulationConfig config = new SimulationConfig(tickRate, clock, timeLimit, waitFor, lockstepDeadline,
                    SimulationConfig.DEFAULT.agentsPerSession(), BodyLimits.DEFAULT);
            checkResume();
            LongFunction<World> worlds = worlds();
            ActorSystem<Void> system = ActorSystem.create(Behaviors.empty(), NodeSettings.SYSTEM,
                    NodeSettings.of(bind, clusterPort, seedNodes, downAfter));
            try {
                Cluster cluster = Cluster.get(system);
                if (seedNodes.isEmpty()) {
                    cluster.manager().tell(Join.create(cluster.selfMember().address()));
                }
                World world = worlds.apply(seed);
                ParcelGrid grid = SplitGame.grid(world, config, parcelSize);
                ShardedParcels parcels = new ShardedParcels(system, grid);
                Gateway gateway = new Gateway((int) (cluster.selfMember().uniqueAddress().longUid() & 0x7fffffffL),
                        world.bounds(), config);
                AtomicLong takenUp = new AtomicLong();
                ActorRef<TickCommand> tick = ClusterSingleton.get(system).init(SingletonActor.of(TickSingleton.create(
                        new TickSingleton.Setup(making(config, parcels, worlds), parcels, gateway, checkpoint, checkpointEvery,
                                resume, takenUp)), "tick"));
                ShardedParcels.host(system, grid, world, config, tick);
                ActorRef<GatewayCommand> actor = system.systemActorOf(Gateway.behavior(gateway), "gateway",
                        Props.empty());
                gateway.attach(ActorRefResolver.get(system).toSerializationFormat(actor), tick);
                system.receptionist().tell(Receptionist.register(Gateway.KEY, actor));
                NetServer net = NetServer.start(new InetSocketAddress(bind, port), gateway, token, operatorToken,
                        NetLimits.DEFAULT);
                return new ClusterNode(system, net, gateway, tick, takenUp);
            } catch (IOException | RuntimeException e) {
                system.terminate();
                throw e;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                system.terminate();
                throw new IOException("interrupted while binding port " + port, e);
            }
        }

        /** How the tick makes its game on this node: new from the seed, or from a saved one. */
        private TickGames making(SimulationConfig config, ShardedParcels parcels, LongFunction<World> worlds) {
            long worldSeed = seed;
            double size = parcelSize;
            Duration reservation = nameReservation;
            Path recording = record;
            java.util.function.BiFunction<World, Recorder, SplitGame> game = (world, recorder) -> {
                SplitGame made = new SplitGame(world, config, worldSeed, Version.current(), recorder, List.of(), size,
                        (name, radius) -> null, g -> parcels);
                made.reserveDroppedNames(reservation);
                return made;
            };
            return new TickGames(
                    recorder -> game.apply(worlds.apply(worldSeed), recorder),
                    (recorder, saved) -> {
                        SplitGame made = game.apply(World.fromScenario(saved.world()), recorder);
                        made.restore(saved);
                        return made;
                    },
                    append -> open(recording, append));
        }

        /** The world of a new game by its seed: the scenario's, read now, or the one the seed makes. */
        private LongFunction<World> worlds() throws IOException {
            if (scenario == null) {
                return worldSeed -> WorldGenerator.standard(worldSeed).generate();
            }
            Scenario read;
            try {
                read = ScenarioFile.read(scenario);
            } catch (IOException e) {
                throw new IOException("cannot read the scenario file " + scenario + " (--scenario): " + e.getMessage(),
                        e);
            }
            return worldSeed -> World.fromScenario(read);
        }

        /** A saved game to go on with must be of this node's world: its seed. */
        private void checkResume() throws IOException {
            if (resume != null) {
                Checkpoint saved = CheckpointFile.read(resume);
                if (saved.seed() != seed) {
                    throw new IllegalArgumentException("the saved game " + resume + " is of seed " + saved.seed()
                            + ", this node's world of seed " + seed + ": start the node with --seed " + saved.seed());
                }
            }
        }

        private static Recorder open(Path file, boolean append) {
            if (file == null) {
                return Recorder.NONE;
            }
            try {
                return FileRecorder.open(file, append);
            } catch (IOException e) {
                throw new UncheckedIOException("cannot record to " + file, e);
            }
        }
    }
}
