package io.orchard.server.sim;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.protocol.message.PerceptionRequestMessage;
import io.orchard.protocol.message.RegisterMessage;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.Role;
import io.orchard.protocol.value.Vec3;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.LongStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What a recording holds when its server stops without warning: every tick up to the last that ended. */
class FileRecorderTest {

    private static final Pattern TICK = Pattern.compile("\"msg\":\\{\"type\":\"Tick\",\"tick\":(\\d+)");

    @TempDir
    Path dir;

    @Test
    void aServerStoppedWithoutClosingItsRecordingLeavesEveryTickUpToTheLastThatEnded() throws Exception {
        Path file = dir.resolve("game.ndjson");
        // Never closed nor flushed by the test: what the file holds at each step is what a kill there leaves.
        FileRecorder recorder = FileRecorder.open(file);
        Simulation sim = new Simulation(TestWorlds.small(), new SimulationConfig(20, ClockMode.REALTIME, 30, 0,
                Duration.ofSeconds(1), 8, BodyLimits.DEFAULT), 7, "test", recorder, List.of(),
                (name, radius) -> Vec3.ground(0, 0));
        FakeSession agent = new FakeSession(1, Role.AGENT);
        sim.connected(agent);
        sim.received(agent, new RegisterMessage(1, "Guppy", TestWorlds.BODY, null));
        sim.applyNow();
        for (long tick = 0; tick < 40; tick++) {
            sim.beginTick();
            sim.received(agent, new PerceptionRequestMessage(tick + 2, "Guppy", 0));
            sim.endTick();

            String text = Files.readString(file, StandardCharsets.UTF_8);
            assertThat(text).endsWith("\n");
            List<Long> ticks = TICK.matcher(text).results().map(m -> Long.parseLong(m.group(1))).toList();
            assertThat(ticks).as("after tick %d", tick).isEqualTo(LongStream.rangeClosed(0, tick).boxed().toList());
            // the tick's end is there too: what the agent asked for in it was accepted and recorded
            assertThat(text).containsPattern("\\{\"tick\":" + tick + ",\"time\":[0-9.E-]+,\"dir\":\"in\",\"client\":\"Guppy\","
                    + "\"msg\":\\{\"type\":\"PerceptionRequest\"");
        }
    }
}
