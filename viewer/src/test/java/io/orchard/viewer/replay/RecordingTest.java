package io.orchard.viewer.replay;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.protocol.message.AgentAddedMessage;
import io.orchard.protocol.message.FruitRemovedMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.viewer.GameFixture;
import io.orchard.viewer.world.WorldMirror;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class RecordingTest {

    @TempDir
    static Path dir;
    static Path recorded;

    @BeforeAll
    static void recordTheScriptedGame() throws Exception {
        recorded = GameFixture.sharedScripted();
    }

    @Test
    void replayStartsFromTheSnapshotAndKeepsWhatViewersSee() throws IOException {
        Recording recording = Recording.read(recorded);

        List<ServerMessage> messages = recording.entries().stream().map(Recording.Entry::message).toList();
        assertThat(messages).filteredOn(m -> m instanceof WorldSnapshotMessage).hasSize(1);
        assertThat(messages).filteredOn(m -> m instanceof AgentAddedMessage).hasSize(2);
        assertThat(messages).filteredOn(m -> m instanceof FruitRemovedMessage).hasSize(1);
        assertThat(messages).noneMatch(m -> m instanceof PerceptionMessage);
        assertThat(recording.startTime()).isZero();
        assertThat(recording.endTime()).isGreaterThan(3.5);
        assertThat(recording.skippedLines()).isZero();
    }

    @Test
    void entriesComeInTimeOrder() throws IOException {
        List<Recording.Entry> entries = Recording.read(recorded).entries();
        for (int i = 1; i < entries.size(); i++) {
            assertThat(entries.get(i).time()).isGreaterThanOrEqualTo(entries.get(i - 1).time());
        }
    }

    @Test
    void replayedIntoAMirrorTheCoconutIsEatenAndTheWalkerArrives() throws IOException {
        WorldMirror mirror = new WorldMirror();
        Recording.read(recorded).entries().forEach(e -> mirror.apply(e.message(), e.time()));

        assertThat(mirror.fruit()).extracting(f -> f.id()).doesNotContain("F1").contains("F2");
        assertThat(mirror.scores().get(0).agent()).isEqualTo("Walker");
        assertThat(mirror.gameOver()).isPresent();
    }

    @Test
    void linesThatAreNotMessagesAreSkippedAndCounted() throws IOException {
        List<String> lines = new ArrayList<>(Files.readAllLines(recorded));
        lines.add(3, "this is not json");
        lines.add("{\"tick\":80,\"time\":4.0,\"dir\":\"out\",\"to\":\"all\",\"msg\":{\"type\":\"Tick\",\"ti");
        Path damaged = dir.resolve("damaged.ndjson");
        Files.write(damaged, lines, StandardCharsets.UTF_8);

        Recording recording = Recording.read(damaged);

        assertThat(recording.skippedLines()).isEqualTo(2);
        assertThat(recording.firstSkipped()).isEqualTo("line 4 is not a JSON object (expected '{' at column 1 but found"
                + " 't')");
        assertThat(recording.entries()).hasSameSizeAs(Recording.read(recorded).entries());
    }

    @Test
    void aLineThatIsNotUtf8IsSkippedNamingItsLineAndByteAndTheRestReplays() throws IOException {
        List<byte[]> lines = new ArrayList<>(Files.readAllLines(recorded).stream()
                .map(line -> line.getBytes(StandardCharsets.UTF_8)).toList());
        lines.add(3, new byte[] {'{', '"', 't', (byte) 0xc3, '"', '}'}); // a two-byte sequence cut short
        Path damaged = dir.resolve("not-utf8.ndjson");
        try (var out = Files.newOutputStream(damaged)) {
            for (byte[] line : lines) {
                out.write(line);
                out.write('\n');
            }
        }

        Recording recording = Recording.read(damaged);

        assertThat(recording.skippedLines()).isEqualTo(1);
        assertThat(recording.firstSkipped()).isEqualTo("line 4 is not UTF-8 text (a malformed byte sequence at byte 4"
                + " of 6)");
        assertThat(recording.entries()).hasSameSizeAs(Recording.read(recorded).entries());
    }

    @Test
    void aFileOfSomethingElseIsRefusedNamingItsFirstBadLine() throws IOException {
        Path notes = Files.writeString(dir.resolve("notes.txt"), "not json at all\nnor this\n");

        assertThatThrownBy(() -> Recording.read(notes))
                .isInstanceOf(IOException.class)
                .hasMessage("cannot replay " + notes + ": line 1 is not a JSON object (expected '{' at column 1 but found"
                        + " 'n'); 2 of its 2 lines could not be read, and no WorldSnapshot line was found to start"
                        + " from");
    }

    @Test
    void aFolderIsNotARecording() {
        assertThatThrownBy(() -> Recording.read(dir))
                .isInstanceOf(IOException.class)
                .hasMessage("cannot read the recording " + dir + ": it is a folder, not a file");
    }

    @Test
    void aRecordingWithoutAViewerCannotBeReplayedAndSaysWhy() throws IOException {
        Path agentsOnly = dir.resolve("agents-only.ndjson");
        Files.write(agentsOnly, Files.readAllLines(recorded).stream()
                .filter(line -> !line.contains("\"type\":\"WorldSnapshot\"")).toList(), StandardCharsets.UTF_8);

        assertThatThrownBy(() -> Recording.read(agentsOnly))
                .isInstanceOf(IOException.class)
                .hasMessageContaining("holds no WorldSnapshot line")
                .hasMessageContaining("connect a viewer while the server records");
    }

    @Test
    void aMissingFileIsNamed() {
        assertThatThrownBy(() -> Recording.read(dir.resolve("nowhere.ndjson")))
                .isInstanceOf(IOException.class)
                .hasMessageContaining("no recording at")
                .hasMessageContaining("nowhere.ndjson");
    }
}
