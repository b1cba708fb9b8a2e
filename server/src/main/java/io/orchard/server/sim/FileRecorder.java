package io.orchard.server.sim;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.Message;
import java.io.ByteArrayOutputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Writes a game's record as newline-delimited JSON, one line per message:
 * {@code {"tick":12,"time":0.6,"dir":"in","client":"Dwarf","msg":{...}}} for a message the server
 * accepted, {@code "dir":"out"} with {@code "to":"client"|"all"|"viewers"|"agents"} for one it sent
 * (and {@code "client"} when it went to one client), and
 * {@code {"tick":12,"time":0.6,"dir":"missed","client":"Dwarf","agents":["Dwarf"],"turn":"deadline"}}
 * for a lockstep turn the game went on without ({@link MissedTurn}). Clients are named by labels
 * (see {@link Recorder}), times are simulated, never the wall clock, so the same game gives the same
 * bytes. Resume tokens are left out: a record may be shared.
 *
 * <p>Lines are collected and written at the end of every half tick, whole lines in one write, so
 * that a killed server leaves a record of complete lines up to its last tick.
 */
public final class FileRecorder implements Recorder {

    private static final int WRITE_AT = 1 << 16;

    private final FileOutputStream out;
    private final ByteArrayOutputStream pending = new ByteArrayOutputStream(WRITE_AT);
    private final MessageCodec codec = new MessageCodec();

    private FileRecorder(FileOutputStream out) {
        this.out = out;
    }

    /** Opens (and truncates) {@code file} for recording. */
    public static FileRecorder open(Path file) throws IOException {
        return open(file, false);
    }

    /** Opens {@code file} for recording, after what it holds when {@code append} (a resumed game goes on). */
    public static FileRecorder open(Path file, boolean append) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        return new FileRecorder(new FileOutputStream(file.toFile(), append));
    }

    @Override
    public void accepted(long tick, double time, String client, Message message) {
        write(tick, time, "\"dir\":\"in\",\"client\":\"" + client + "\",\"msg\":" + codec.encode(message));
    }

    @Override
    public void sent(long tick, double time, Audience to, String client, Message message) {
        String audience = to.name().toLowerCase(Locale.ROOT);
        write(tick, time, "\"dir\":\"out\",\"to\":\"" + audience + "\""
                + (to == Audience.CLIENT ? ",\"client\":\"" + client + "\"" : "") + ",\"msg\":"
                + codec.encode(message));
    }

    @Override
    public void missed(long tick, double time, String client, MissedTurn missed) {
        // Labels and agents' names are letters, digits, '_' and '-': nothing to escape.
        write(tick, time, "\"dir\":\"missed\",\"client\":\"" + client + "\",\"agents\":["
                + String.join(",", missed.agents().stream().map(a -> "\"" + a + "\"").toList()) + "],\"turn\":\""
                + missed.kind().wireName() + "\"");
    }

    private void write(long tick, double time, String fields) {
        byte[] line = ("{\"tick\":" + tick + ",\"time\":" + time + "," + fields + "}\n")
                .getBytes(StandardCharsets.UTF_8);
        pending.write(line, 0, line.length);
        if (pending.size() >= WRITE_AT) {
            flush();
        }
    }

    @Override
    public void flush() {
        if (pending.size() == 0) {
            return;
        }
        try {
            pending.writeTo(out);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the recording", e);
        } finally {
            pending.reset();
        }
    }

    @Override
    public void close() {
        try {
            flush();
        } finally {
            try {
                out.close();
            } catch (IOException e) {
                throw new UncheckedIOException("cannot close the recording", e);
            }
        }
    }
}
