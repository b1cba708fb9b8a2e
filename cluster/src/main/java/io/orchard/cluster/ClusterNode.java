package io.orchard.cluster;

import io.orchard.cluster.game.SplitGame;
import io.orchard.cluster.node.Gateway;
import io.orchard.cluster.node.GatewayCommand;
import io.orchard.cluster.node.NodeSettings;
import io.orchard.cluster.node.ParcelEntity;
import io.orchard.cluster.node.ShardedParcels;
import io.orchard.cluster.node.TickCommand;
import io.orchard.cluster.node.TickSingleton;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.cluster.parcel.ParcelId;
import io.orchard.protocol.value.ClockMode;
import io.orchard.server.Version;
import io.orchard.server.net.NetLimits;
import io.orchard.server.net.NetServer;
import io.orchard.server.sim.BodyLimits;
import io.orchard.server.sim.FileRecorder;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.ActorRefResolver;
import org.apache.pekko.actor.typed.ActorSystem;
import org.apache.pekko.actor.typed.Props;
import org.apache.pekko.actor.typed.javadsl.AskPattern;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
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

    private ClusterNode(ActorSystem<Void> system, NetServer net, Gateway gateway) {
        this.system = system;
        this.net = net;
        this.gateway = gateway;
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

    /** Configures a {@link ClusterNode}; every setter checks its value and names it when it is wrong. */
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

        private Builder() {}

        /** The address the gateway and the cluster member listen on; loopback by default. */
        public Builder bind(String address) {
            this.bind = Objects.requireNonNull(address, "bind address");
            return this;
        }

        /** The port agents and viewers connect to, 0 for any free one. */
        public Builder port(int port) {
            this.port = checkPort(port, "port");
            return this;
        }

        /** The port of the node's cluster member, 0 for any free one. */
        public Builder clusterPort(int port) {
            this.clusterPort = checkPort(port, "cluster port");
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
            this.tickRate = tickRate;
            return this;
        }

        /** The game's length in simulated seconds. */
        public Builder timeLimit(double seconds) {
            this.timeLimit = seconds;
            return this;
        }

        /** Start the game only when this many agents have registered (0: at the first). */
        public Builder waitFor(int agents) {
            this.waitFor = agents;
            return this;
        }

        /** In lockstep, how long a tick waits for agents that have not ended their turn. */
        public Builder lockstepDeadline(Duration deadline) {
            this.lockstepDeadline = Objects.requireNonNull(deadline, "lockstep deadline");
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

        /** Record the game to this file, on the node where the tick runs. */
        public Builder record(Path file) {
            this.record = Objects.requireNonNull(file, "record file");
            return this;
        }

        private static int checkPort(int port, String what) {
            if (port < 0 || port > 65535) {
                throw new IllegalArgumentException(what + " must be 0 to 65535, was " + port);
            }
            return port;
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
            ActorSystem<Void> system = ActorSystem.create(Behaviors.empty(), NodeSettings.SYSTEM,
                    NodeSettings.of(bind, clusterPort, seedNodes));
            try {
                Cluster cluster = Cluster.get(system);
                if (seedNodes.isEmpty()) {
                    cluster.manager().tell(Join.create(cluster.selfMember().address()));
                }
                World world = WorldGenerator.standard(seed).generate();
                ParcelGrid grid = SplitGame.grid(world, config, parcelSize);
                ShardedParcels parcels = ShardedParcels.start(system, grid, world, config);
                Path recording = record;
                long worldSeed = seed;
                ActorRef<TickCommand> tick = ClusterSingleton.get(system).init(SingletonActor.of(
                        TickSingleton.create(recorder -> new SplitGame(world, config, worldSeed, Version.current(),
                                recorder, List.of(), parcelSize, (name, radius) -> null, g -> parcels),
                                () -> open(recording)), "tick"));
                Gateway gateway = new Gateway(cluster.selfMember().address().getPort().orElseThrow(), tick,
                        world.bounds(), config);
                ActorRef<GatewayCommand> actor = system.systemActorOf(Gateway.behavior(gateway), "gateway",
                        Props.empty());
                gateway.attach(ActorRefResolver.get(system).toSerializationFormat(actor));
                NetServer net = NetServer.start(new InetSocketAddress(bind, port), gateway, null, null,
                        NetLimits.DEFAULT);
                return new ClusterNode(system, net, gateway);
            } catch (IOException | RuntimeException e) {
                system.terminate();
                throw e;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                system.terminate();
                throw new IOException("interrupted while binding port " + port, e);
            }
        }

        private static Recorder open(Path file) {
            if (file == null) {
                return Recorder.NONE;
            }
            try {
                return FileRecorder.open(file);
            } catch (IOException e) {
                throw new UncheckedIOException("cannot record to " + file, e);
            }
        }
    }
}
