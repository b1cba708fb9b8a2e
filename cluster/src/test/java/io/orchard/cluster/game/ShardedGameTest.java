package io.orchard.cluster.game;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.cluster.node.Keeper;
import io.orchard.cluster.node.NodeSettings;
import io.orchard.cluster.node.ParcelEntity;
import io.orchard.cluster.node.ShardedParcels;
import io.orchard.cluster.node.TickCommand;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.server.sim.Placement;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.apache.pekko.actor.typed.ActorRef;
import org.apache.pekko.actor.typed.Props;
import org.apache.pekko.actor.typed.ActorSystem;
import org.apache.pekko.actor.typed.javadsl.AskPattern;
import org.apache.pekko.actor.typed.javadsl.Behaviors;
import org.apache.pekko.cluster.MemberStatus;
import org.apache.pekko.cluster.sharding.ShardRegion.CurrentShardRegionState;
import org.apache.pekko.cluster.sharding.typed.ClusterShardingQuery;
import org.apache.pekko.cluster.sharding.typed.GetShardRegionState;
import org.apache.pekko.cluster.sharding.typed.javadsl.ClusterSharding;
import org.apache.pekko.cluster.typed.Cluster;
import org.apache.pekko.cluster.typed.Join;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A lockstep game of 30 deterministic agents on the single server's simulation, and on a cluster of
 * three Pekko nodes in this JVM (each its own actor system on a loopback port, its messages to the
 * others serialized), whose parcels of 25 units are sharded entities spread over the three; halfway
 * through, the third node leaves the cluster (as Ctrl-C leaves it), and its parcels go to the other
 * two with all they held: the two recordings are the same file, byte for byte.
 */
class ShardedGameTest {

    @TempDir
    Path dir;

    private final List<ActorSystem<Void>> nodes = new ArrayList<>();

    @AfterEach
    void stopTheNodes() throws Exception {
        for (ActorSystem<Void> node : nodes) {
            node.terminate();
        }
        for (ActorSystem<Void> node : nodes) {
            node.getWhenTerminated().toCompletableFuture().get(60, TimeUnit.SECONDS);
        }
    }

    private ActorSystem<Void> node() {
        ActorSystem<Void> node = ActorSystem.create(Behaviors.empty(), NodeSettings.SYSTEM,
                NodeSettings.of("127.0.0.1", 0, List.of()));
        nodes.add(node);
        return node;
    }

    @Test
    void threeNodesPlayTheSingleServersGameByteForByteEvenWhenOneLeaves() throws Exception {
        SimulationConfig config = Games.lockstep(30, 20);
        Placement anywhere = (name, radius) -> null;
        Path single = Games.single(dir, Games.world(), config, anywhere, Games.foragers(30, 1));

        ActorSystem<Void> first = node();
        Cluster.get(first).manager().tell(Join.create(Cluster.get(first).selfMember().address()));
        for (int i = 0; i < 2; i++) {
            ActorSystem<Void> other = node();
            Cluster.get(other).manager().tell(Join.create(Cluster.get(first).selfMember().address()));
        }
        awaitMembersUp(first, 3);
        World world = Games.world();
        ParcelGrid grid = SplitGame.grid(world, config, 25);
        AtomicLong takenUp = new AtomicLong();
        ActorRef<TickCommand> keeper = first.systemActorOf(Keeper.behavior(takenUp), "keeper", Props.empty());
        for (ActorSystem<Void> node : nodes) {
            ShardedParcels.host(node, grid, Games.world(), config, keeper);
        }
        ShardedParcels parcels = new ShardedParcels(first, grid);
        ActorSystem<Void> leaving = nodes.get(2);
        List<Integer> hosted = new ArrayList<>();

        SplitCounts counts = Games.split(dir, world, config, anywhere, Games.foragers(30, 2), g -> parcels, tick -> {
            if (tick == 200) {
                hosted.addAll(entitiesPerNode());
                leave(leaving);
                awaitMembersUp(first, 2);
            }
        });
        System.out.printf("three nodes, then two: %s; parcels per node before one left %s, %d with agents taken "
                + "up by the others%n", counts, hosted, takenUp.get());

        Games.sameRecordings(dir, single);
        assertThat(counts.handOvers()).as("agents walked from parcel to parcel").isPositive();
        assertThat(hosted).as("every node hosted parcels").hasSize(3).allMatch(count -> count > 0);
        assertThat(takenUp.get()).as("parcels with agents that the leaving node gave to the others")
                .isPositive();
    }

    /** The node leaves the cluster as a node's Ctrl-C has it: its actor system ends, its parcels handed off. */
    private void leave(ActorSystem<Void> node) {
        node.terminate();
        try {
            node.getWhenTerminated().toCompletableFuture().get(60, TimeUnit.SECONDS);
        } catch (Exception e) {
            throw new AssertionError("the node did not leave within 60 s", e);
        }
    }

    private static void awaitMembersUp(ActorSystem<Void> node, int count) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline) {
            long up = 0;
            for (org.apache.pekko.cluster.Member member : Cluster.get(node).state().getMembers()) {
                if (member.status() == MemberStatus.up()) {
                    up++;
                }
            }
            if (up == count) {
                return;
            }
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError(e);
            }
        }
        throw new AssertionError("the cluster did not have " + count + " nodes up within 60 s");
    }

    /** How many parcels each node hosts. */
    private List<Integer> entitiesPerNode() {
        List<Integer> counts = new ArrayList<>();
        for (ActorSystem<Void> node : nodes) {
            try {
                CurrentShardRegionState state = AskPattern.<ClusterShardingQuery, CurrentShardRegionState>ask(
                        ClusterSharding.get(node).shardState(),
                        replyTo -> new GetShardRegionState(ParcelEntity.TYPE, replyTo), Duration.ofSeconds(10),
                        node.scheduler()).toCompletableFuture().get(20, TimeUnit.SECONDS);
                counts.add(state.getShards().stream().mapToInt(shard -> shard.getEntityIds().size()).sum());
            } catch (Exception e) {
                throw new AssertionError("a node did not say which parcels it hosts", e);
            }
        }
        return counts;
    }
}
