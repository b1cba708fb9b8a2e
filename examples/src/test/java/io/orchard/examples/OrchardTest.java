package io.orchard.examples;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import io.orchard.examples.schema.ProtocolSchema;
import io.orchard.protocol.ProtocolVersion;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class OrchardTest {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String... args) {
        return Orchard.run(args, print(out), print(err));
    }

    private int run(Orchard launcher, String... args) {
        return launcher.run(List.of(args), print(out), print(err));
    }

    private String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    private String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    private static PrintStream print(ByteArrayOutputStream bytes) {
        return new PrintStream(bytes, true, StandardCharsets.UTF_8);
    }

    @ParameterizedTest(name = "\"{0}\"")
    @ValueSource(strings = {"--help", "-h", "help"})
    void helpListsTheCommandsWithTheirSummaries(String option) {
        assertThat(run(option)).isZero();
        assertThat(out())
                .contains("Usage: ./orchard <command> [options]")
                .containsPattern("\n  protocol-schema +Print the JSON Schema of every protocol message\n")
                .contains("--version");
        assertThat(err()).isEmpty();
    }

    @Test
    void noArgumentsShowTheHelp() {
        assertThat(run()).isZero();
        assertThat(out()).contains("Usage: ./orchard <command> [options]", "protocol-schema");
    }

    @Test
    void versionNamesOrchardAndTheProtocolVersion() {
        assertThat(run("--version")).isZero();
        assertThat(out()).matches("orchard \\S+ \\(protocol " + ProtocolVersion.CURRENT + "\\)\\R");
        assertThat(Orchard.version()).doesNotContain("${");
    }

    @Test
    void unknownCommandExitsWith2NamingItAndListingTheCommands() {
        assertThat(run("frobnicate", "--fast")).isEqualTo(2);
        assertThat(err()).contains("unknown command 'frobnicate'", "protocol-schema");
        assertThat(out()).isEmpty();
    }

    @Test
    void unknownOptionExitsWith2NamingIt() {
        assertThat(run("--frobnicate")).isEqualTo(2);
        assertThat(err()).contains("unknown option '--frobnicate'");
    }

    @Nested
    class ProtocolSchemaSubcommand {

        @Test
        void printsTheSchema() {
            assertThat(run("protocol-schema")).isZero();
            assertThat(out()).isEqualTo(ProtocolSchema.json());
        }

        @Test
        void writesTheSchemaToTheOutFile(@TempDir Path directory) throws IOException {
            Path file = directory.resolve("protocol.schema.json");
            assertThat(run("protocol-schema", "--out", file.toString())).isZero();
            assertThat(Files.readString(file, StandardCharsets.UTF_8)).isEqualTo(ProtocolSchema.json());
            assertThat(out()).isEmpty();
        }

        @Test
        void failsWith1WhenTheOutDirectoryIsMissing(@TempDir Path directory) {
            Path file = directory.resolve("missing").resolve("protocol.schema.json");
            assertThat(run("protocol-schema", "--out=" + file)).isEqualTo(1);
            assertThat(err()).contains("orchard protocol-schema: cannot write " + file, "does not exist");
        }

        @ParameterizedTest(name = "{0}")
        @ValueSource(strings = {"protocol-schema --help", "help protocol-schema", "protocol-schema --out x --help"})
        void answersHelp(String line) {
            assertThat(run(line.split(" "))).isZero();
            assertThat(out()).startsWith("Usage: ./orchard protocol-schema [--out FILE]").contains("--out FILE");
        }

        @Test
        void rejectsAnUnknownArgumentWith2() {
            assertThat(run("protocol-schema", "--pretty")).isEqualTo(2);
            assertThat(err()).contains("unexpected argument '--pretty'", "./orchard protocol-schema --help");
        }

        @Test
        void rejectsOutWithoutAFileWith2() {
            assertThat(run("protocol-schema", "--out")).isEqualTo(2);
            assertThat(err()).contains("--out needs a file name");
        }
    }

    @Nested
    class Dispatch {

        @Test
        void aFailingCommandExitsWith1AndPrintsItsMessage() {
            Orchard launcher = new Orchard(List.of(new Stub("explode", new IOException("the disk is full"))));
            assertThat(run(launcher, "explode")).isEqualTo(1);
            assertThat(err()).isEqualTo("orchard explode: the disk is full" + System.lineSeparator());
        }

        @Test
        void argumentsAfterTheNameReachTheCommand() {
            Stub stub = new Stub("echo", null);
            assertThat(run(new Orchard(List.of(stub)), "echo", "a", "b")).isZero();
            assertThat(stub.received).containsExactly("a", "b");
        }

        @Test
        void twoCommandsWithOneNameAreRefused() {
            assertThatThrownBy(() -> new Orchard(List.of(new Stub("twice", null), new Stub("twice", null))))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("'twice'");
        }

        @Test
        void commandNamesAreUnique() {
            assertThat(Orchard.COMMANDS).extracting(Command::name).doesNotHaveDuplicates();
        }
    }

    /** A command that records its arguments and then fails with the given exception, if any. */
    private static final class Stub implements Command {

        private final String name;
        private final Exception failure;
        private List<String> received;

        Stub(String name, Exception failure) {
            this.name = name;
            this.failure = failure;
        }

        @Override
        public String name() {
            return name;
        }

        @Override
        public String summary() {
            return "A stand-in";
        }

        @Override
        public String help() {
            return "Usage: ./orchard " + name + "\n";
        }

        @Override
        public int run(List<String> args, PrintStream out, PrintStream err) throws Exception {
            received = args;
            if (failure != null) {
                throw failure;
            }
            return 0;
        }
    }
}
