package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.value.ClockMode;
import io.orchard.server.sim.BodyLimits;
import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.CheckpointFile;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.sim.TestWorlds;
import io.orchard.protocol.value.Vec3;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CheckpointsTest {

    @TempDir
    Path dir;

    private static Checkpoint checkpointOfTick0() {
        Simulation simulation = new Simulation(TestWorlds.small(), new SimulationConfig(20, ClockMode.LOCKSTEP, 30, 0,
                Duration.ofSeconds(1), 8, BodyLimits.DEFAULT), 11, "test", Recorder.NONE, List.of(),
                (name, radius) -> Vec3.ground(0, 0));
        return simulation.checkpoint();
    }

    @Test
    void aCheckpointOfferedJustBeforeCloseIsStillWritten() throws Exception {
        // The last checkpoint of a game is offered as the game ends, and the server closes right after.
        Path file = dir.resolve("game.json");
        Checkpoints checkpoints = new Checkpoints(file);
        checkpoints.offer(checkpointOfTick0());
        checkpoints.close();
        assertThat(file).exists();
        assertThat(CheckpointFile.read(file).seed()).isEqualTo(11);
    }
}
