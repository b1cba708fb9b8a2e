package io.orchard.server.sim;

import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.Message;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Writes a game's record as newline-delimited JSON, one line per message:
 * {@code {"tick":12,"time":0.6,"dir":"in","session":3,"msg":{...}}} for a message the server
 * accepted, {@code "dir":"out"} with {@code "to":"client"|"all"|"viewers"|"agents"} for one it sent.
 * Times are simulated, never the wall clock, so the same game gives the same bytes. Each line is
 * flushed as it is written: a killed server leaves a record up to its last message.
 */
public final class FileRecorder implements Recorder {

    private final BufferedWriter out;
    private final MessageCodec codec = new MessageCodec();

    private FileRecorder(BufferedWriter out) {
        this.out = out;
    }

    /** Opens (and truncates) {@code file} for recording. */
    public static FileRecorder open(Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        return new FileRecorder(Files.newBufferedWriter(file, StandardCharsets.UTF_8));
    }

    @Override
    public void accepted(long tick, double time, long session, Message message) {
        write(tick, time, "\"dir\":\"in\",\"session\":" + session, message);
    }

    @Override
    public void sent(long tick, double time, Audience to, long session, Message message) {
        String audience = to.name().toLowerCase(Locale.ROOT);
        write(tick, time, "\"dir\":\"out\",\"to\":\"" + audience + "\""
                + (to == Audience.CLIENT ? ",\"session\":" + session : ""), message);
    }

    private void write(long tick, double time, String fields, Message message) {
        try {
            out.write("{\"tick\":" + tick + ",\"time\":" + time + "," + fields + ",\"msg\":" + codec.encode(message) + "}\n");
            out.flush();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the recording", e);
        }
    }

    @Override
    public void close() {
        try {
            out.close();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot close the recording", e);
        }
    }
}
