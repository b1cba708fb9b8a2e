package io.orchard.examples.match;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;

/** Output folders of the programs that write files. */
public final class Folders {

    private static final DateTimeFormatter STAMP = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss");

    private Folders() {}

    /**
     * A new folder in the working directory named after the program and the time, such as
     * {@code demo-20260122-101500}, so that one run never overwrites another's files.
     */
    public static Path fresh(String program) throws IOException {
        String base = program + "-" + LocalDateTime.now().format(STAMP);
        Path dir = Path.of(base);
        for (int i = 2; Files.exists(dir); i++) {
            dir = Path.of(base + "-" + i);
        }
        return Files.createDirectories(dir);
    }

    /**
     * The folder given with {@code --out}, created when missing.
     *
     * @throws IOException naming the path when it is a file or cannot be created
     */
    public static Path given(Path dir) throws IOException {
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw new IOException("--out must be a folder, and " + dir + " is a file");
        }
        return Files.createDirectories(dir);
    }
}
