package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.agents.zoo.Guppy;
import io.orchard.agents.zoo.Recording;
import io.orchard.agents.zoo.Robot;
import io.orchard.protocol.value.Point2;
import io.orchard.server.sim.GameListener;
import io.orchard.server.world.Bank;
import io.orchard.server.world.World;
import io.orchard.server.world.WorldGenerator;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * "Go to the castle" told on the other bank of the river, in real recorded lockstep games: the agent
 * knows the castle only as the compass sector it lies in, and the spot its estimate put before the
 * castle lay in the river; it once gave up there with "I can't find a way to the castle". It now
 * stands where it may around the estimate, crosses by a bridge and gets there.
 */
class CastleAcrossTheRiverGameTest {

    @TempDir
    Path recordings;

    @Test
    void theRobotOnTheNorthBankGoesOverABridgeToTheCastleOnTheSouthBank() throws Exception {
        reachesTheCastle(2012, new Point2(0, -75), new Robot(), Bank.NORTH);
    }

    @Test
    void guppyOnTheEastBankGoesOverABridgeToTheCastleOnTheWestBank() throws Exception {
        reachesTheCastle(1, new Point2(40, 70), new Guppy(), Bank.EAST);
    }

    private void reachesTheCastle(long seed, Point2 start, AgentController agent, Bank bank) throws Exception {
        World world = WorldGenerator.standard(seed).generate();
        Point2 castle = world.castle().centre();
        assertThat(world.bankOf(start)).as("precondition: the start's bank").contains(bank);
        assertThat(world.bankOf(castle)).as("precondition: the castle across the river").isPresent().get()
                .isNotEqualTo(bank);
        List<String> said = new CopyOnWriteArrayList<>();
        AtomicLong tick = new AtomicLong();
        AtomicLong arrived = new AtomicLong(-1);
        agent.addSpeechListener(line -> {
            said.add(line);
            if (line.startsWith("I'm at the castle.")) {
                arrived.compareAndSet(-1, tick.get());
            }
        });
        agent.instruct("go to the castle");
        Path file = recordings.resolve(agent.name() + ".ndjson");
        GameListener clock = new GameListener() {
            @Override
            public void tickEnded(long ended, double time) {
                tick.set(ended);
            }
        };

        Games.recorded(seed, 60, List.of(agent), Games.at(Map.of(agent.name(), start.at(0))), clock, file);

        assertThat(said).as("said").contains("Going to the castle.")
                .anyMatch(line -> line.startsWith("I'm at the castle."))
                .noneMatch(line -> line.contains("can't find a way"));
        Recording recording = Recording.read(file, agent.name());
        List<Recording.Tick> ticks = recording.ticks();
        Point2 there = ticks.stream().filter(t -> t.tick() >= arrived.get()).findFirst().orElseThrow().at();
        assertThat(there.distance(castle)).as("where it said it was at the castle").isLessThan(20);
        assertThat(ticks).as("in the water").noneMatch(t -> world.river().contains(t.at())
                && world.bridges().stream().noneMatch(b -> b.covers(t.at())));
        assertThat(ticks).as("over a bridge").anyMatch(t -> world.bridges().stream().anyMatch(b -> b.covers(t.at())));
    }
}
