package io.orchard.agents;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.OpenOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.regex.Pattern;

/**
 * A file of resume tokens, a line for each agent: its name, a space, its token; lines starting
 * with {@code #} are comments. Several controllers may share one, in this program and in others:
 * a change takes a lock (a lock in this JVM, then a file lock on {@code <file>.lock} beside it),
 * reads the file, and writes it whole to a temporary file in the same folder that is then renamed
 * over it, so that a reader or a crash finds the old file or the new one, never half of one. A
 * temporary file that a killed writer left ({@code <file><digits>.partial}) is deleted under the
 * lock by the next change, or by {@link #removeLeftovers()} when a program starts.
 *
 * <p>Where the file system has POSIX permissions, the file, its lock and a folder made for them
 * are their owner's alone (mode 600, 700 for the folder). Elsewhere (Windows) they take the access
 * rules of their folder, which in the user's home are the user's alone.
 */
final class ResumeTokenFile {

    private static final String PARTIAL = ".partial";
    private static final Set<PosixFilePermission> OWNER_ONLY = PosixFilePermissions.fromString("rw-------");
    private static final Set<PosixFilePermission> OWNER_ONLY_FOLDER = PosixFilePermissions.fromString("rwx------");
    private static final String HEADER = "# Orchard resume tokens: an agent's name, then the token that gets it back."
            + " Keep them private.\n";
    /** A JVM may not hold two file locks on one file: its threads take turns here first. */
    private static final Map<Path, Object> LOCKS = new ConcurrentHashMap<>();

    private final Path file;
    private final boolean posix;

    /** The file at {@code file}, with owner-only permissions where the file system has POSIX ones. */
    ResumeTokenFile(Path file) {
        this(file, true);
    }

    /** With {@code posix} false, no permissions are set even where they could be, as on Windows. */
    ResumeTokenFile(Path file, boolean posix) {
        this.file = file.toAbsolutePath().normalize();
        this.posix = posix;
    }

    Path path() {
        return file;
    }

    /** The tokens by agent name; none when there is no file yet. Lines that are not name and token are skipped. */
    Map<String, String> read() throws IOException {
        Map<String, String> tokens = new TreeMap<>();
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            return tokens;
        }
        for (String line : text.split("\n")) {
            int space = line.indexOf(' ');
            if (!line.startsWith("#") && space > 0 && space < line.length() - 1) {
                tokens.put(line.substring(0, space), line.substring(space + 1).strip());
            }
        }
        return tokens;
    }

    /** Reads the tokens, lets {@code change} change them, and writes them back, all under the lock. */
    void update(Consumer<Map<String, String>> change) throws IOException {
        locked(folder -> {
            Map<String, String> tokens = read();
            change.accept(tokens);
            write(folder, tokens);
        });
    }

    /**
     * Deletes the temporary files that writers killed before their rename left, as every change
     * does first: for a program starting, which may not write for a while. Nothing when there is
     * no folder yet.
     */
    void removeLeftovers() throws IOException {
        if (Files.isDirectory(file.getParent())) {
            locked(folder -> { });
        }
    }

    private interface UnderLock {
        void run(Path folder) throws IOException;
    }

    /** Runs {@code work} holding the lock, after deleting what killed writers left. */
    private void locked(UnderLock work) throws IOException {
        Path folder = file.getParent();
        createFolder(folder);
        synchronized (LOCKS.computeIfAbsent(file, f -> new Object())) {
            Path lockFile = folder.resolve(file.getFileName() + ".lock");
            Set<OpenOption> options = Set.of(StandardOpenOption.CREATE, StandardOpenOption.WRITE);
            try (FileChannel lock = posixHere(folder)
                    ? FileChannel.open(lockFile, options, PosixFilePermissions.asFileAttribute(OWNER_ONLY))
                    : FileChannel.open(lockFile, options)) {
                lock.lock(); // held until the channel closes
                removeLeftovers(folder);
                work.run(folder);
            }
        }
    }

    private void write(Path folder, Map<String, String> tokens) throws IOException {
        StringBuilder text = new StringBuilder(HEADER);
        tokens.forEach((agent, token) -> text.append(agent).append(' ').append(token).append('\n'));
        String prefix = file.getFileName().toString();
        Path temporary = posixHere(folder)
                ? Files.createTempFile(folder, prefix, PARTIAL, PosixFilePermissions.asFileAttribute(OWNER_ONLY))
                : Files.createTempFile(folder, prefix, PARTIAL);
        try {
            try (FileChannel out = FileChannel.open(temporary, StandardOpenOption.WRITE,
                    StandardOpenOption.TRUNCATE_EXISTING)) {
                ByteBuffer bytes = StandardCharsets.UTF_8.encode(text.toString());
                while (bytes.hasRemaining()) {
                    out.write(bytes);
                }
                out.force(true);
            }
            try {
                Files.move(temporary, file, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temporary, file, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    /** Deletes the temporary files of writes that were cut short; called under the lock, so none is under way. */
    private void removeLeftovers(Path folder) throws IOException {
        Pattern leftover = Pattern.compile(Pattern.quote(file.getFileName().toString()) + "\\d+"
                + Pattern.quote(PARTIAL));
        try (DirectoryStream<Path> found = Files.newDirectoryStream(folder,
                f -> leftover.matcher(f.getFileName().toString()).matches())) {
            for (Path partial : found) {
                Files.deleteIfExists(partial);
            }
        }
    }

    private void createFolder(Path folder) throws IOException {
        if (Files.isDirectory(folder)) {
            return;
        }
        if (posix) {
            try {
                Files.createDirectories(folder, PosixFilePermissions.asFileAttribute(OWNER_ONLY_FOLDER));
                return;
            } catch (UnsupportedOperationException e) {
                // not a POSIX file system: the folder takes its parent's rules
            }
        }
        Files.createDirectories(folder);
    }

    private boolean posixHere(Path folder) throws IOException {
        return posix && Files.getFileStore(folder).supportsFileAttributeView(PosixFileAttributeView.class);
    }
}
