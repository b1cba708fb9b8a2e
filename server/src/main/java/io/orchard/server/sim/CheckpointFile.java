package io.orchard.server.sim;

import io.orchard.protocol.StrictJson;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import tools.jackson.core.JacksonException;
import tools.jackson.databind.json.JsonMapper;

/**
 * Reads and writes checkpoint files: one {@link Checkpoint} as UTF-8 JSON. Writing is atomic: the
 * checkpoint goes to a temporary file beside the target, is forced to the disk, and is then renamed
 * over the target, so a crash at any moment leaves either the old checkpoint or the new one, never
 * half of one. Reading is strict, like scenario files. Thread-safe.
 *
 * <p>A checkpoint holds every agent's resume token: whoever can read it can take over the agents.
 * The file is written readable by its owner only where the file system allows.
 */
public final class CheckpointFile {

    private static final JsonMapper MAPPER = StrictJson.builder().build();

    private CheckpointFile() {}

    /** Writes the checkpoint to {@code file} atomically, replacing what was there. */
    public static void write(Checkpoint checkpoint, Path file) throws IOException {
        byte[] json;
        try {
            json = MAPPER.writeValueAsBytes(checkpoint);
        } catch (JacksonException e) {
            throw new IOException("cannot encode the checkpoint: " + e.getOriginalMessage(), e);
        }
        Path target = file.toAbsolutePath();
        Path dir = target.getParent();
        Files.createDirectories(dir);
        Path temporary = Files.createTempFile(dir, target.getFileName().toString(), ".partial");
        try {
            try (FileChannel channel = FileChannel.open(temporary, StandardOpenOption.WRITE,
                    StandardOpenOption.TRUNCATE_EXISTING)) {
                ByteBuffer buffer = ByteBuffer.wrap(json);
                while (buffer.hasRemaining()) {
                    channel.write(buffer);
                }
                channel.force(true);
            }
            try {
                Files.move(temporary, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    /**
     * Reads a checkpoint file.
     *
     * @throws IOException when the file cannot be read or is not a checkpoint, naming the problem
     */
    public static Checkpoint read(Path file) throws IOException {
        byte[] json = Files.readAllBytes(file);
        try {
            return MAPPER.readValue(json, Checkpoint.class);
        } catch (JacksonException e) {
            throw new IOException(file + " is not a checkpoint this server can read: " + e.getOriginalMessage(), e);
        }
    }
}
