package io.orchard.agents;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ResumeTokenFileTest {

    @TempDir
    Path dir;

    private boolean posix() throws Exception {
        return Files.getFileStore(dir).supportsFileAttributeView(PosixFileAttributeView.class);
    }

    private static String mode(Path path) throws Exception {
        return PosixFilePermissions.toString(Files.getPosixFilePermissions(path));
    }

    private List<String> folder(Path folder) throws Exception {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(f -> f.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void tokensAreKeptALineAnAgentAndReadBack() throws Exception {
        ResumeTokenFile file = new ResumeTokenFile(dir.resolve("tokens"));
        assertThat(file.read()).isEmpty();

        file.update(tokens -> tokens.put("Dwarf", "0123456789abcdef0123456789abcdef"));
        file.update(tokens -> tokens.put("Guppy", "fedcba9876543210fedcba9876543210"));
        file.update(tokens -> tokens.remove("Dwarf"));

        assertThat(file.read()).isEqualTo(Map.of("Guppy", "fedcba9876543210fedcba9876543210"));
        assertThat(Files.readString(dir.resolve("tokens"))).endsWith("\nGuppy fedcba9876543210fedcba9876543210\n")
                .startsWith("# ");
    }

    @Test
    void theFileItsLockAndAFolderMadeForThemAreTheOwnersAlone() throws Exception {
        Path folder = dir.resolve("home").resolve(".orchard");
        ResumeTokenFile file = new ResumeTokenFile(folder.resolve("resume-tokens"));
        file.update(tokens -> tokens.put("Dwarf", "0123456789abcdef0123456789abcdef"));

        assertThat(folder(folder)).containsExactly("resume-tokens", "resume-tokens.lock");
        if (posix()) {
            assertThat(mode(folder)).isEqualTo("rwx------");
            assertThat(mode(folder.resolve("resume-tokens"))).isEqualTo("rw-------");
            assertThat(mode(folder.resolve("resume-tokens.lock"))).isEqualTo("rw-------");
        }
    }

    @Test
    void aFileReadableByOthersBecomesTheOwnersAloneWhenItIsNextWritten() throws Exception {
        Path path = Files.writeString(dir.resolve("tokens"), "Dwarf 0123456789abcdef0123456789abcdef\n");
        if (posix()) {
            Files.setPosixFilePermissions(path, PosixFilePermissions.fromString("rw-r--r--"));
        }
        new ResumeTokenFile(path).update(tokens -> tokens.put("Guppy", "fedcba9876543210fedcba9876543210"));

        assertThat(new ResumeTokenFile(path).read()).containsOnlyKeys("Dwarf", "Guppy");
        if (posix()) {
            assertThat(mode(path)).isEqualTo("rw-------");
        }
    }

    @Test
    void withoutPosixPermissionsTheFileIsWrittenAllTheSame() throws Exception {
        ResumeTokenFile file = new ResumeTokenFile(dir.resolve("sub").resolve("tokens"), false);
        file.update(tokens -> tokens.put("Dwarf", "0123456789abcdef0123456789abcdef"));

        assertThat(file.read()).isEqualTo(Map.of("Dwarf", "0123456789abcdef0123456789abcdef"));
        assertThat(folder(dir.resolve("sub"))).containsExactly("tokens", "tokens.lock");
    }

    @Test
    void whatAWriterKilledBeforeItsRenameLeftIsRemovedByTheNextChangeAndNothingElse() throws Exception {
        Path path = dir.resolve("tokens");
        // Files.createTempFile's names, as a write cut short leaves them
        Files.writeString(dir.resolve("tokens5132889061727718443.partial"), "Dwarf 0123");
        Files.writeString(dir.resolve("tokens.partial"), "not one of ours");
        Files.writeString(dir.resolve("other7.partial"), "not one of ours");

        new ResumeTokenFile(path).update(tokens -> tokens.put("Dwarf", "0123456789abcdef0123456789abcdef"));

        assertThat(folder(dir)).containsExactly("other7.partial", "tokens", "tokens.lock", "tokens.partial");
    }

    @Test
    void whatAKilledWriterLeftIsRemovedWhenAProgramStartsEvenBeforeItWrites() throws Exception {
        Path path = Files.writeString(dir.resolve("tokens"), "Dwarf 0123456789abcdef0123456789abcdef\n");
        Files.writeString(dir.resolve("tokens977.partial"), "Dwarf 0123");

        new ResumeTokens(new ResumeTokenFile(path), "Dwarf").toPresent();

        assertThat(folder(dir)).containsExactly("tokens", "tokens.lock");
        assertThat(Files.readString(path)).isEqualTo("Dwarf 0123456789abcdef0123456789abcdef\n"); // not rewritten
        new ResumeTokenFile(dir.resolve("none").resolve("tokens")).removeLeftovers();
        assertThat(dir.resolve("none")).doesNotExist();
    }

    @Test
    void linesThatAreNotANameAndATokenAreSkipped() throws Exception {
        Path path = Files.writeString(dir.resolve("tokens"), "# a comment\n\nDwarf\n Robot x\nBunny 0123 \r\n",
                StandardCharsets.UTF_8);
        assertThat(new ResumeTokenFile(path).read()).isEqualTo(Map.of("Bunny", "0123"));
    }

    @Test
    void agentsOfOneProgramWritingAtOnceLoseNoLine() throws Exception {
        ResumeTokenFile file = new ResumeTokenFile(dir.resolve("tokens"));
        List<Thread> writers = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            String agent = "Agent" + i;
            writers.add(new Thread(() -> {
                for (int round = 0; round < 20; round++) {
                    String token = agent + "-" + round;
                    try {
                        file.update(tokens -> tokens.put(agent, token));
                    } catch (java.io.IOException e) {
                        throw new java.io.UncheckedIOException(e);
                    }
                }
            }));
        }
        writers.forEach(Thread::start);
        for (Thread writer : writers) {
            writer.join();
        }
        assertThat(file.read()).hasSize(8).allSatisfy((agent, token) -> assertThat(token).isEqualTo(agent + "-19"));
        assertThat(folder(dir)).containsExactly("tokens", "tokens.lock");
    }

    @Test
    void programsWritingAtOnceLoseNoLine() throws Exception {
        Path path = dir.resolve("tokens");
        Process other = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), Writer.class.getName(), path.toString(), "Other", "100")
                .redirectErrorStream(true).start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!new ResumeTokenFile(path).read().containsKey("Other0") && other.isAlive()) {
            assertThat(System.nanoTime()).as("the other program's first line").isLessThan(deadline);
            Thread.sleep(5);
        }
        Writer.main(new String[] {path.toString(), "Here", "40"});
        assertThat(other.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(other.exitValue()).as(new String(other.getInputStream().readAllBytes(), StandardCharsets.UTF_8))
                .isZero();

        Map<String, String> tokens = new ResumeTokenFile(path).read();
        assertThat(tokens).containsAllEntriesOf(Map.of("Here0", "t", "Other0", "t", "Here39", "t", "Other99", "t"));
        assertThat(tokens).hasSize(140);
    }

    /** Adds the lines {@code <prefix>0 t} to {@code <prefix><count - 1> t}, one change each: for another program. */
    static final class Writer {
        public static void main(String[] args) throws Exception {
            ResumeTokenFile file = new ResumeTokenFile(Path.of(args[0]));
            IntStream.range(0, Integer.parseInt(args[2])).forEach(i -> {
                try {
                    file.update(tokens -> tokens.put(args[1] + i, "t"));
                } catch (java.io.IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            });
        }
    }
}
