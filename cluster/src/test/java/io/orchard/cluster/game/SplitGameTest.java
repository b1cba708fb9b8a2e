package io.orchard.cluster.game;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.sim.Placement;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The same lockstep game of 30 deterministic agents, played by the single server's simulation and by
 * a game whose world is cut into parcels of 25 units (64 of them) in this JVM, connected in another
 * order: the two recordings are the same file, byte for byte, and in the split game agents walked
 * from parcel to parcel, saw agents in other parcels, grasped fruit in other parcels and walked paths
 * beyond their parcels' halos.
 */
class SplitGameTest {

    @TempDir
    Path dir;

    @Test
    void aGameCutIntoParcelsIsTheSingleServersGameByteForByte() throws Exception {
        SimulationConfig config = Games.lockstep(30, 60);
        Placement anywhere = (name, radius) -> null;
        Path single = Games.single(dir, Games.world(), config, anywhere, Games.foragers(30, 1));
        World world = Games.world();
        SplitCounts counts = Games.split(dir, world, config, anywhere, Games.foragers(30, 2),
                grid -> new LocalParcels(grid, world, config));
        String text = Files.readString(single, StandardCharsets.UTF_8);
        System.out.printf("recording of %d bytes; %s%n", text.length(), counts);
        assertThat(text).as("the game was played").contains("\"type\":\"FruitEaten\"", "\"type\":\"GameOver\"")
                .doesNotContain("\"dir\":\"missed\"");
        Games.sameRecordings(dir, single);
        assertThat(counts.handOvers()).as("agents walked from parcel to parcel").isPositive();
        assertThat(counts.sightingsAcrossBorders()).as("agents saw agents in other parcels").isPositive();
        assertThat(counts.graspsAcrossBorders()).as("agents grasped fruit in other parcels").isPositive();
        assertThat(counts.pathsBeyondHalo()).as("paths left their parcels' halos").isPositive();
    }

    /**
     * Eight agents that meet again and again where four parcels' corners touch, bumping into each
     * other across the borders: those that could touch are walked together, and the game is still
     * the single server's, stop for stop.
     */
    @Test
    void agentsThatBumpIntoEachOtherAcrossBordersAreWalkedAsOnOneServer() throws Exception {
        World world = Games.world();
        Vec3 corner = freeCorner(world);
        SimulationConfig config = Games.lockstep(8, 15);
        Placement ring = (name, radius) -> {
            double angle = (name.charAt(name.length() - 1) - '0') * Math.PI / 4;
            return Vec3.ground(corner.x() + 3 * Math.cos(angle), corner.z() + 3 * Math.sin(angle));
        };
        Path single = Games.single(dir, world, config, ring, crowders(corner));
        World again = Games.world();
        SplitCounts counts = Games.split(dir, again, config, ring, crowders(corner),
                grid -> new LocalParcels(grid, again, config));
        assertThat(Files.readString(single)).as("agents stopped when they met").contains("\"duration\":0.0");
        Games.sameRecordings(dir, single);
        assertThat(counts.walkedTogether()).as("agents walked together across borders").isPositive();
    }

    private static List<Player> crowders(Vec3 meeting) {
        List<Player> agents = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            agents.add(new Crowder("Crowder" + i, new TestSession(i + 1, Role.AGENT), meeting));
        }
        return agents;
    }

    /** A point where four parcels of 25 meet, with room around it for a ring of eight agents. */
    private static Vec3 freeCorner(World world) {
        for (int x = -75; x <= 75; x += 25) {
            for (int z = -75; z <= 75; z += 25) {
                if (world.checkPlace(new Point2(x, z), 4).isFree()) {
                    return Vec3.ground(x, z);
                }
            }
        }
        throw new AssertionError("no free corner in the world");
    }
}
