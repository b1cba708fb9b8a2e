package io.orchard.server;

import io.orchard.server.sim.Checkpoint;
import io.orchard.server.sim.CheckpointFile;
import io.orchard.server.sim.FileRecorder;
import io.orchard.server.world.scenario.Scenario;
import io.orchard.server.world.scenario.ScenarioFile;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The files a server starts from and writes to, opened so that a failure names the file and the
 * option that gave it: the JDK's own message is the bare path ("/nonexistent.json").
 */
final class GameFiles {

    private static final Logger LOG = LoggerFactory.getLogger(GameFiles.class);

    private GameFiles() {}

    /** The scenario of {@code --scenario}. */
    static Scenario scenario(Path file) throws IOException {
        try {
            return ScenarioFile.read(file);
        } catch (IOException e) {
            throw unreadable("scenario file", "--scenario", file, e);
        }
    }

    /** The saved game of {@code --resume}. */
    static Checkpoint checkpoint(Path file) throws IOException {
        try {
            return CheckpointFile.read(file);
        } catch (NoSuchFileException | AccessDeniedException e) {
            throw unreadable("checkpoint", "--resume", file, e);
        } catch (IOException e) {
            if (Files.isDirectory(file)) {
                throw unreadable("checkpoint", "--resume", file, e);
            }
            throw e; // it names the file and what is wrong with what it holds
        }
    }

    /**
     * Deletes what writes of the checkpoint {@code file} (null: none) left unfinished when a process
     * was killed during one, and logs each file deleted. A folder that cannot be read is logged, and
     * the server starts all the same: the checkpoint's own write will say what is wrong with it.
     */
    static void removeLeftovers(Path file) {
        if (file == null) {
            return;
        }
        try {
            for (Path leftover : CheckpointFile.removeLeftovers(file)) {
                LOG.info("removed {}, left by a checkpoint's write that was cut short", leftover);
            }
        } catch (IOException e) {
            LOG.warn("cannot look for unfinished checkpoint writes beside {}: {}", file, e.toString());
        }
    }

    /**
     * The recording of {@code --record}, after what the file holds when {@code append}. A missing
     * folder is created, and the log says so, so that a mistyped folder does not go unnoticed.
     */
    static FileRecorder recorder(Path file, boolean append) throws IOException {
        Path folder = file.toAbsolutePath().getParent();
        try {
            if (folder != null && !Files.isDirectory(folder)) {
                Files.createDirectories(folder);
                LOG.info("created the folder {} for the recording {}", folder, file);
            }
            return FileRecorder.open(file, append);
        } catch (IOException e) {
            throw new IOException("cannot record to " + file + " (--record): " + reason(file, e), e);
        }
    }

    private static IOException unreadable(String what, String option, Path file, IOException e) {
        return new IOException("cannot read the " + what + " " + file + " (" + option + "): " + reason(file, e), e);
    }

    private static String reason(Path file, IOException e) {
        if (e instanceof NoSuchFileException) {
            return "no such file";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileAlreadyExistsException exists) {
            return exists.getFile() + " is a file, not a folder";
        }
        if (Files.isDirectory(file)) {
            return "it is a folder, not a file";
        }
        return e.getMessage();
    }
}
