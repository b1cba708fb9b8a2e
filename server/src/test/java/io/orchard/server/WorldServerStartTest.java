package io.orchard.server;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import io.orchard.protocol.value.Score;
import java.io.IOException;
import java.net.BindException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.slf4j.LoggerFactory;

/** What a server says when it cannot start, and what it tells about the files it makes. */
class WorldServerStartTest {

    @TempDir
    Path dir;

    @Test
    void aTakenPortIsNamedWithWhatToDo() throws IOException {
        try (WorldServer first = WorldServer.builder().port(0).seed(1).start()) {
            assertThatThrownBy(() -> WorldServer.builder().port(first.port()).seed(1).start())
                    .isInstanceOf(BindException.class)
                    .hasMessage("cannot listen on port " + first.port() + ": address already in use (is another server"
                            + " running? choose another with --port)");
        }
    }

    @Test
    void aBrowserViewerWithoutTheWebModuleIsRefusedSayingWhatIsMissing() throws IOException {
        try (WorldServer plain = WorldServer.builder().port(0).seed(1).start()) {
            assertThat(plain.httpPort()).as("HTTP port of a server not asked for one").isEmpty();
        }
        // The server module's tests run without the web module, as a program that embeds it may.
        assertThatThrownBy(() -> WorldServer.builder().port(0).httpPort(0).seed(1).start())
                .isInstanceOf(IOException.class)
                .hasMessage("cannot serve the browser viewer on port 0: the web module (io.orchard:web) is not on"
                        + " the class path (expected it beside the server, as ./orchard has it)");
        assertThatThrownBy(() -> WorldServer.builder().httpPort(65536))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("HTTP port must be 0 to 65535, was 65536");
    }

    @Test
    void anAddressThatIsNotThisMachinesIsNamed() {
        assertThatThrownBy(() -> WorldServer.builder().port(0).bind("192.0.2.1").seed(1).start())
                .isInstanceOf(BindException.class)
                .hasMessageStartingWith("cannot listen on 192.0.2.1: it is not an address of this machine");
    }

    @Test
    void aMissingScenarioNamesTheFileAndTheOption() {
        Path missing = dir.resolve("nonexistent.json");

        assertThatThrownBy(() -> WorldServer.builder().port(0).scenario(missing).start())
                .isInstanceOf(IOException.class)
                .hasMessage("cannot read the scenario file " + missing + " (--scenario): no such file");
    }

    @Test
    void aFolderGivenAsTheScenarioIsNamed() {
        assertThatThrownBy(() -> WorldServer.builder().port(0).scenario(dir).start())
                .isInstanceOf(IOException.class)
                .hasMessage("cannot read the scenario file " + dir + " (--scenario): it is a folder, not a file");
    }

    @Test
    void aMissingSavedGameNamesTheFileAndTheOption() {
        Path missing = dir.resolve("nonexistent.json");

        assertThatThrownBy(() -> WorldServer.builder().port(0).resume(missing).start())
                .isInstanceOf(IOException.class)
                .hasMessage("cannot read the checkpoint " + missing + " (--resume): no such file");
    }

    @Test
    void whatACheckpointWriteCutShortLeftIsRemovedAtStartAndNothingElse() throws IOException {
        Path checkpoint = dir.resolve("game.json");
        // Files.createTempFile's names, as a write killed before its rename leaves them
        Path leftover = Files.writeString(dir.resolve("game.json8406131295447466421.partial"), "{\"format\":2,\"see");
        Path another = Files.writeString(dir.resolve("game.json17.partial"), "");
        List<Path> kept = List.of(Files.writeString(dir.resolve("game.json.partial"), "mine"),
                Files.writeString(dir.resolve("other.json123.partial"), "not this server's"),
                Files.writeString(dir.resolve("game.json123.partial.bak"), "mine too"));
        Logger log = (Logger) LoggerFactory.getLogger(GameFiles.class);
        ListAppender<ILoggingEvent> logged = new ListAppender<>();
        logged.start();
        log.addAppender(logged);
        try (WorldServer server = WorldServer.builder().port(0).seed(1).checkpoint(checkpoint, null).start()) {
            assertThat(leftover).doesNotExist();
            assertThat(another).doesNotExist();
            assertThat(kept).allMatch(Files::exists);
            assertThat(logged.list).extracting(ILoggingEvent::getFormattedMessage)
                    .contains("removed " + leftover + ", left by a checkpoint's write that was cut short");
        } finally {
            log.detachAppender(logged);
        }
    }

    @Test
    void aRecordingIntoAMissingFolderCreatesItAndSaysSo() throws IOException {
        Path recording = dir.resolve("runs").resolve("today").resolve("game.ndjson");
        Logger log = (Logger) LoggerFactory.getLogger(GameFiles.class);
        ListAppender<ILoggingEvent> said = new ListAppender<>();
        said.start();
        log.addAppender(said);
        try (WorldServer server = WorldServer.builder().port(0).seed(1).record(recording).start()) {
            assertThat(recording.getParent()).isDirectory();
        } finally {
            log.detachAppender(said);
        }
        assertThat(recording).isRegularFile();
        assertThat(said.list).extracting(ILoggingEvent::getFormattedMessage)
                .containsExactly("created the folder " + recording.getParent() + " for the recording " + recording);
    }

    @Test
    void aRecordingIntoAnExistingFolderSaysNothingAboutIt() throws IOException {
        Logger log = (Logger) LoggerFactory.getLogger(GameFiles.class);
        ListAppender<ILoggingEvent> said = new ListAppender<>();
        said.start();
        log.addAppender(said);
        try (WorldServer server = WorldServer.builder().port(0).seed(1).record(dir.resolve("game.ndjson")).start()) {
            assertThat(said.list).isEmpty();
        } finally {
            log.detachAppender(said);
        }
    }

    @Test
    void aRecordingWhereAFileStandsForTheFolderIsRefusedNamingIt() throws IOException {
        Path file = Files.writeString(dir.resolve("runs"), "not a folder");

        assertThatThrownBy(() -> WorldServer.builder().port(0).seed(1).record(file.resolve("game.ndjson")).start())
                .isInstanceOf(IOException.class)
                .hasMessage("cannot record to " + file.resolve("game.ndjson") + " (--record): " + file
                        + " is a file, not a folder");
    }

    @Test
    void theStatusLineShowsScoresAsPeopleWriteThem() {
        assertThat(WorldServer.scores(List.of(new Score("FirstAgent", 2, 1), new Score("Dwarf", 1, 1),
                new Score("Bunny", 0, 0)))).isEqualTo("FirstAgent 2 points (1 fruit), Dwarf 1 point (1 fruit),"
                        + " Bunny 0 points (0 fruit)");
        assertThat(WorldServer.scores(List.of())).isEqualTo("none");
    }
}
