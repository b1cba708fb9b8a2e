package io.orchard.viewer.replay;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.ProtocolException;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.protocol.value.Nullable;
import java.io.IOException;
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
    private final String firstProblem;

    private Recording(Path file, List<Entry> entries, int skipped, String firstProblem) {
        this.file = file;
        this.entries = List.copyOf(entries);
        this.skipped = skipped;
        this.firstProblem = firstProblem;
    }

    /**
     * Reads a recording. Lines that cannot be read (not UTF-8, not JSON, not a message) are
     * skipped, counted and logged with the first of them, so that a recording cut short by a crash
     * still replays.
     *
     * @throws IOException when the file cannot be read, or holds no world snapshot to start from;
     *                     the message names the file and, when lines were skipped, the first of
     *                     them and what is wrong with it
     */
    public static Recording read(Path file) throws IOException {
        MessageCodec codec = new MessageCodec();
        List<Entry> entries = new ArrayList<>();
        List<Entry> beforeSnapshot = new ArrayList<>();
        String snapshotSession = null;
        int skipped = 0;
        String firstProblem = null;
        int lineNumber = 0;
        try (Utf8Lines in = new Utf8Lines(Files.newInputStream(file))) {
            while (true) {
                String problem;
                try {
                    String line = in.next();
                    if (line == null) {
                        break;
                    }
                    lineNumber = in.number();
                    if (line.isBlank()) {
                        continue;
                    }
                    RecordLine record = parse(line);
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
                    continue;
                } catch (IllegalArgumentException e) {
                    problem = e.getMessage();
                } catch (ProtocolException e) {
                    problem = "holds no message this viewer reads (" + e.getMessage() + ")";
                }
                lineNumber = in.number();
                if (skipped++ == 0) {
                    firstProblem = "line " + lineNumber + " " + problem;
                }
            }
        } catch (NoSuchFileException e) {
            throw new IOException("no recording at " + file + " (no such file)", e);
        } catch (IOException e) {
            throw new IOException("cannot read the recording " + file + ": "
                    + (Files.isDirectory(file) ? "it is a folder, not a file" : e.getMessage()), e);
        }
        if (snapshotSession == null && skipped > 0) {
            throw new IOException("cannot replay " + file + ": " + firstProblem + "; " + skipped + " of its "
                    + lineNumber + " lines could not be read, and no WorldSnapshot line was found to start"
                    + " from");
        }
        if (snapshotSession == null) {
            throw new IOException("recording " + file + " holds no WorldSnapshot line (read " + lineNumber
                    + " lines): it was recorded with no viewer connected; connect a viewer while the server records");
        }
        if (skipped > 0) {
            LOG.warn("recording {}: skipped {} line(s) that could not be read; the first: {}", file, skipped,
                    firstProblem);
        }
        return new Recording(file, entries, skipped, firstProblem);
    }

    private static RecordLine parse(String line) {
        try {
            return RecordLine.parse(line);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("is not a JSON object (" + e.getMessage() + ")", e);
        }
    }

    private static ServerMessage decode(MessageCodec codec, String json) {
        if (json == null) {
            throw new IllegalArgumentException("has no \"msg\" field");
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

    /**
     * The first line skipped and what is wrong with it ("line 2 is not UTF-8 text (a malformed byte
     * sequence at byte 1 of 9)"); null when none was.
     */
    public @Nullable String firstSkipped() {
        return firstProblem;
    }
}
