package io.orchard.viewer.replay;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.ProtocolException;
import io.orchard.protocol.message.ServerMessage;
import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A recorded game, as much of it as a viewer shows: read from the file a server writes with
 * {@code --record}. The world is rebuilt from the first {@code WorldSnapshot} in the file (sent to
 * the viewer that was connected) and the {@code AgentAdded} lines sent with it; after it, every
 * message the server sent to all clients or to viewers is kept with its simulated time. Perceptions
 * and other messages for one agent are skipped without being decoded.
 *
 * <p>A game recorded with no viewer connected has no snapshot and cannot be replayed; connect a
 * viewer (even a headless one) while recording.
 */
public final class Recording {

    private static final Logger LOG = LoggerFactory.getLogger(Recording.class);
    private static final Set<String> BROADCAST = Set.of("all", "viewers");

    /**
     * One message to replay.
     *
     * @param time    the simulated time it was sent, in seconds
     * @param message the message
     */
    public record Entry(double time, ServerMessage message) {
    }

    private final Path file;
    private final List<Entry> entries;
    private final int skipped;

    private Recording(Path file, List<Entry> entries, int skipped) {
        this.file = file;
        this.entries = List.copyOf(entries);
        this.skipped = skipped;
    }

    /**
     * Reads a recording.
     *
     * @throws IOException when the file cannot be read, or holds no world snapshot to start from
     */
    public static Recording read(Path file) throws IOException {
        MessageCodec codec = new MessageCodec();
        List<Entry> entries = new ArrayList<>();
        List<Entry> beforeSnapshot = new ArrayList<>();
        String snapshotSession = null;
        int skipped = 0;
        int firstSkipped = 0;
        String firstProblem = null;
        int lineNumber = 0;
        try (BufferedReader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            String line;
            while ((line = in.readLine()) != null) {
                lineNumber++;
                if (line.isBlank()) {
                    continue;
                }
                try {
                    RecordLine record = RecordLine.parse(line);
                    if (!"out".equals(record.get("dir"))) {
                        continue;
                    }
                    String to = record.get("to");
                    String type = record.messageType();
                    boolean wanted;
                    if (snapshotSession == null) {
                        wanted = "WorldSnapshot".equals(type) || "GameStarted".equals(type);
                    } else {
                        wanted = BROADCAST.contains(to) || ("client".equals(to) && "AgentAdded".equals(type)
                                && snapshotSession.equals(record.get("session")));
                    }
                    if (!wanted) {
                        continue;
                    }
                    Entry entry = new Entry(record.number("time", 0), decode(codec, record.get("msg")));
                    if (snapshotSession == null && "WorldSnapshot".equals(type)) {
                        snapshotSession = record.get("session") == null ? "" : record.get("session");
                        entries.addAll(beforeSnapshot);
                        entries.add(entry);
                    } else if (snapshotSession == null) {
                        beforeSnapshot.add(entry);
                    } else {
                        entries.add(entry);
                    }
                } catch (IllegalArgumentException | ProtocolException e) {
                    if (skipped++ == 0) {
                        firstSkipped = lineNumber;
                        firstProblem = e.getMessage();
                    }
                }
            }
        } catch (NoSuchFileException e) {
            throw new IOException("no recording at " + file + " (no such file)", e);
        }
        if (snapshotSession == null) {
            throw new IOException("recording " + file + " holds no WorldSnapshot line (read " + lineNumber
                    + " lines): it was recorded with no viewer connected; connect a viewer while the server records");
        }
        if (skipped > 0) {
            LOG.warn("recording {}: skipped {} line(s) that are not messages, the first at line {}: {}", file, skipped,
                    firstSkipped, firstProblem);
        }
        return new Recording(file, entries, skipped);
    }

    private static ServerMessage decode(MessageCodec codec, String json) {
        if (json == null) {
            throw new IllegalArgumentException("line has no \"msg\" field");
        }
        return codec.decodeServer(json);
    }

    /** The file it was read from. */
    public Path file() {
        return file;
    }

    /** The messages to replay, in the order they were sent; the snapshot is among the first. */
    public List<Entry> entries() {
        return entries;
    }

    /** The simulated time of the snapshot, where replay starts. */
    public double startTime() {
        for (Entry entry : entries) {
            if (entry.message() instanceof io.orchard.protocol.message.WorldSnapshotMessage) {
                return entry.time();
            }
        }
        return 0;
    }

    /** The simulated time of the last message. */
    public double endTime() {
        return entries.isEmpty() ? 0 : entries.get(entries.size() - 1).time();
    }

    /** How many lines could not be read as messages and were skipped. */
    public int skippedLines() {
        return skipped;
    }
}
