package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.value.ClockMode;
import io.orchard.server.sim.BodyLimits;
import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.CheckpointFile;
import io.orchard.server.sim.Recorder;
import io.orchard.server.sim.Simulation;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.sim.TestWorlds;
import io.orchard.protocol.value.Vec3;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.List;
import java.util.stream.Stream;
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

    @Test
    void aCheckpointIsItsOwnersAloneAndLeavesNoTemporaryFileBehind() throws Exception {
        Path file = dir.resolve("game.json");
        CheckpointFile.write(checkpointOfTick0(), file);
        CheckpointFile.write(checkpointOfTick0(), file);
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files).containsExactly(file);
        }
        if (Files.getFileStore(dir).supportsFileAttributeView(PosixFileAttributeView.class)) {
            assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(file))).isEqualTo("rw-------");
        }
    }

    @Test
    void aWriteThatFailsBeforeItsRenameLeavesNoTemporaryFileBehind() throws Exception {
        Path folder = Files.createDirectory(dir.resolve("game.json")); // a folder where the file should go
        Files.writeString(folder.resolve("in the way"), "so that the rename over it fails");
        assertThatThrownBy(() -> CheckpointFile.write(checkpointOfTick0(), folder)).isInstanceOf(IOException.class);
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files).containsExactly(folder);
        }
    }

    @Test
    void closingWaitsForTheCheckpointBeingWrittenSoThatNoneIsLeftHalfWritten() throws Exception {
        Path file = dir.resolve("game.json");
        Checkpoints checkpoints = new Checkpoints(file);
        for (int i = 0; i < 20; i++) {
            checkpoints.write(checkpointOfTick0(), file, null);
        }
        checkpoints.close();
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files).containsExactly(file);
        }
        assertThat(CheckpointFile.read(file).seed()).isEqualTo(11);
    }
}
