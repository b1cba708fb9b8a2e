package io.orchard.cluster.game;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.cluster.node.NodeSettings;
import io.orchard.cluster.node.ParcelEntity;
import io.orchard.cluster.node.ShardedParcels;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.server.sim.Placement;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
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
 * others serialized), whose parcels of 25 units are sharded entities spread over the three: the two
 * recordings are the same file, byte for byte.
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
    void threeNodesPlayTheSingleServersGameByteForByte() throws Exception {
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
        ShardedParcels parcels = ShardedParcels.start(first, grid, world, config);
        for (ActorSystem<Void> other : nodes.subList(1, nodes.size())) {
            ShardedParcels.start(other, grid, Games.world(), config);
        }

        SplitCounts counts = Games.split(dir, world, config, anywhere, Games.foragers(30, 2), g -> parcels);
        System.out.printf("three nodes: %s; parcels per node %s%n", counts, entitiesPerNode());

        Games.sameRecordings(dir, single);
        assertThat(counts.handOvers()).as("agents walked from parcel to parcel").isPositive();
        assertThat(entitiesPerNode()).as("every node hosts parcels").allMatch(count -> count > 0);
    }

    private static void awaitMembersUp(ActorSystem<Void> node, int count) throws InterruptedException {
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
            Thread.sleep(100);
        }
        throw new AssertionError("the " + count + " nodes did not come up within 60 s");
    }

    /** How many parcels each node hosts. */
    private List<Integer> entitiesPerNode() throws Exception {
        List<Integer> counts = new ArrayList<>();
        for (ActorSystem<Void> node : nodes) {
            CurrentShardRegionState state = AskPattern.<ClusterShardingQuery, CurrentShardRegionState>ask(
                    ClusterSharding.get(node).shardState(),
                    replyTo -> new GetShardRegionState(ParcelEntity.TYPE, replyTo), Duration.ofSeconds(10),
                    node.scheduler()).toCompletableFuture().get(20, TimeUnit.SECONDS);
            counts.add(state.getShards().stream().mapToInt(shard -> shard.getEntityIds().size()).sum());
        }
        return counts;
    }
}
