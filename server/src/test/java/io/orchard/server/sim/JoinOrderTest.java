package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.message.SayMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Role;
import io.orchard.server.world.WorldGenerator;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** A game of one seed plays out the same whichever client connected or registered first. */
class JoinOrderTest {

    private static final List<String> NAMES = List.of("Dwarf", "Robot", "Bunny", "Guppy", "Roadrunner");

    private static Simulation simulation(long seed) {
        return new Simulation(WorldGenerator.standard(seed).generate(), new SimulationConfig(20, ClockMode.LOCKSTEP,
                30, 0, Duration.ofSeconds(1), 8, BodyLimits.DEFAULT), seed, "test", Recorder.NONE, List.of());
    }

    /** Each agent's AgentAdded line, as a viewer sees it, after the agents joined in {@code order}. */
    private static List<String> join(List<String> order) {
        Simulation sim = simulation(1998);
        FakeSession viewer = new FakeSession(1, Role.VIEWER);
        sim.connected(viewer);
        long id = 10;
        for (String name : order) {
            FakeSession client = new FakeSession(id++, Role.AGENT);
            sim.connected(client);
            sim.received(client, new RegisterMessage(id, name, TestWorlds.BODY, null));
        }
        sim.applyNow();
        List<String> added = new ArrayList<>();
        for (AgentAddedMessage message : viewer.all(AgentAddedMessage.class)) {
            added.add(message.agent().name() + " at " + message.agent().position() + " facing " + message.agent().heading());
        }
        added.sort(null);
        return added;
    }

    @Test
    void agentsStartWhereTheSeedAndTheirNamesPutThemWhoeverCameFirst() {
        List<String> reversed = new ArrayList<>(NAMES);
        java.util.Collections.reverse(reversed);

        assertThat(join(reversed)).hasSize(NAMES.size()).isEqualTo(join(NAMES));
    }

    @Test
    void agentsAreListedByName() {
        Simulation sim = simulation(7);
        long id = 10;
        for (String name : NAMES) {
            FakeSession client = new FakeSession(id++, Role.AGENT);
            sim.connected(client);
            sim.received(client, new RegisterMessage(id, name, TestWorlds.BODY, null));
        }
        sim.applyNow();

        assertThat(sim.agentNames()).containsExactly("Bunny", "Dwarf", "Guppy", "Roadrunner", "Robot");
    }

    @Test
    void whatClientsSayInOneTickIsAppliedInTheOrderOfTheirAgentsNames() {
        Simulation sim = simulation(7);
        FakeSession viewer = new FakeSession(1, Role.VIEWER);
        sim.connected(viewer);
        FakeSession zed = new FakeSession(10, Role.AGENT); // connects first
        FakeSession amy = new FakeSession(11, Role.AGENT);
        sim.connected(zed);
        sim.connected(amy);
        sim.received(zed, new RegisterMessage(1, "Zed", TestWorlds.BODY, null));
        sim.received(amy, new RegisterMessage(1, "Amy", TestWorlds.BODY, null));
        sim.applyNow();

        sim.received(zed, new SayMessage(2, "Zed", "first to speak"));
        sim.received(amy, new SayMessage(2, "Amy", "second to speak"));
        sim.applyNow();

        assertThat(viewer.all(SayMessage.class)).extracting(SayMessage::agent).containsExactly("Amy", "Zed");
    }
}
