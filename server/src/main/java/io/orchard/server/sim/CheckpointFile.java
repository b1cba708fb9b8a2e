package io.orchard.server.sim;

import io.orchard.protocol.StrictJson;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import tools.jackson.core.JacksonException;
import tools.jackson.databind.json.JsonMapper;

/**
 * Reads and writes checkpoint files: one {@link Checkpoint} as UTF-8 JSON. Writing is atomic: the
 * checkpoint goes to a temporary file beside the target, is forced to the disk, and is then renamed
 * over the target, so a crash at any moment leaves either the old checkpoint or the new one, never
 * half of one. Reading is strict, like scenario files. Thread-safe.
 *
 * <p>A checkpoint holds every agent's resume token: whoever can read it can take over the agents.
 * The file is written readable by its owner only where the file system allows (the temporary file
 * is made so, and the rename keeps it). A write cut short by a kill leaves its temporary file,
 * {@code <name><digits>.partial}, which {@link #removeLeftovers} deletes.
 */
public final class CheckpointFile {

    private static final JsonMapper MAPPER = StrictJson.builder().build();
    /** How the temporary file of a write ends, until it is renamed over the checkpoint. */
    private static final String PARTIAL = ".partial";

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
        Path temporary = Files.createTempFile(dir, target.getFileName().toString(), PARTIAL);
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
     * Deletes the temporary files that writes of {@code file} left unfinished (the process was
     * killed in the middle of one): each holds part of a game, resume tokens included, and is of no
     * use. Call it before writing starts, never while another process writes the same file.
     *
     * @return the files deleted
     */
    public static List<Path> removeLeftovers(Path file) throws IOException {
        Path target = file.toAbsolutePath();
        Path dir = target.getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            return List.of();
        }
        // Files.createTempFile names them after the prefix and the suffix with digits between.
        Pattern temporary = Pattern.compile(Pattern.quote(target.getFileName().toString()) + "\\d+"
                + Pattern.quote(PARTIAL));
        List<Path> removed = new ArrayList<>();
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir,
                f -> temporary.matcher(f.getFileName().toString()).matches())) {
            for (Path leftover : files) {
                if (Files.deleteIfExists(leftover)) {
                    removed.add(leftover);
                }
            }
        }
        return removed;
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
