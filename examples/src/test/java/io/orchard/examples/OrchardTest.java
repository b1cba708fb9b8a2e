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
import java.util.concurrent.Callable;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

class OrchardTest {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    private int run(String... args) {
        return Orchard.run(args, print(out), print(err));
    }

    private int run(List<CommandLine> commands, String... args) {
        return Orchard.launcher(commands, print(out), print(err)).execute(args);
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
                .startsWith("Usage: orchard <command> [OPTIONS]")
                .containsPattern("\n  protocol-schema +Print the JSON Schema of every protocol message\n")
                .containsPattern("\n  help +" + Orchard.HELP_SUMMARY + "\n")
                .containsPattern("\n  completion +Print a bash completion script")
                .contains("--version");
        assertThat(err()).isEmpty();
    }

    @Test
    void noArgumentsShowTheHelp() {
        assertThat(run()).isZero();
        assertThat(out()).contains("Usage: orchard <command> [OPTIONS]", "protocol-schema");
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

    @Test
    void helpAnswersItsOwnHelp() {
        assertThat(run("help", "--help")).isZero();
        assertThat(out()).contains("Usage: orchard help [-h] [COMMAND]", "COMMAND");
        assertThat(err()).isEmpty();
    }

    @Test
    void helpOfAnUnknownCommandExitsWith2NamingIt() {
        assertThat(run("help", "frobnicate")).isEqualTo(2);
        assertThat(err()).contains("unknown command 'frobnicate'", "protocol-schema");
        assertThat(out()).isEmpty();
    }

    @Test
    void aBadValueNamesTheCommandTheOptionTheValueAndWhatWasExpected() {
        assertThat(run("server", "--port", "abc")).isEqualTo(2);
        assertThat(err()).isEqualTo("""
                orchard server: invalid value for option '--port': 'abc' is not an integer (expected a port 0-65535)
                Run ./orchard server --help for its options.
                """.replace("\n", System.lineSeparator()));
        assertThat(out()).isEmpty();
    }

    @Test
    void completionPrintsABashScriptOfEveryCommandAndItsOptions() {
        assertThat(run("completion")).isZero();
        assertThat(out()).startsWith("#!/usr/bin/env bash")
                .contains("complete -F _complete_orchard")
                .contains("demo", "server", "viewer", "agents", "first-agent", "tournament", "protocol-schema",
                        "completion", "help")
                .contains("--time-limit", "--checkpoint-every", "--screenshot", "--seed-from")
                .contains("(\"realtime\" \"lockstep\")", "(\"on\" \"off\")",
                        "(\"dwarf\" \"robot\" \"bunny\" \"guppy\" \"roadrunner\")");
        assertThat(err()).isEmpty();
    }

    /** Every command, as named on the command line, and its summary in the launcher's help. */
    @Nested
    class EveryCommand {

        private final List<CommandLine> commands = Orchard.commands(System.in, print(out), print(err));

        @Test
        void answersHelpAsHelpCommandDoesStartingWithItsUsage() {
            for (CommandLine command : commands) {
                String name = command.getCommandName();
                out.reset();
                assertThat(run(name, "--help")).as(name).isZero();
                String help = out();
                out.reset();
                assertThat(run("help", name)).as(name).isZero();

                assertThat(out()).as(name).isEqualTo(help).startsWith("Usage: orchard " + name + " [OPTIONS]")
                        .contains("-h, --help");
            }
            assertThat(err()).isEmpty();
        }

        @Test
        void hasASummaryThatStartsWithACapitalAndEndsWithoutAFullStop() {
            List<String> summaries = new java.util.ArrayList<>(commands.stream()
                    .map(command -> command.getCommandSpec().usageMessage().description()[0]).toList());
            summaries.add(Orchard.HELP_SUMMARY);
            assertThat(summaries).allSatisfy(summary -> assertThat(summary).matches("[A-Z][^\\n]*[^.]"));
        }
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
            assertThat(out()).startsWith("Usage: orchard protocol-schema [OPTIONS]").contains("--out=FILE");
        }

        @Test
        void rejectsAnUnknownArgumentWith2() {
            assertThat(run("protocol-schema", "--pretty")).isEqualTo(2);
            assertThat(err()).contains("orchard protocol-schema: unknown option: '--pretty'",
                    "./orchard protocol-schema --help");
        }

        @Test
        void rejectsOutWithoutAFileWith2() {
            assertThat(run("protocol-schema", "--out")).isEqualTo(2);
            assertThat(err()).contains("missing required parameter for option '--out' (FILE)");
        }
    }

    @Nested
    class Dispatch {

        @Test
        void aFailingCommandExitsWith1AndPrintsItsMessage() {
            assertThat(run(List.of(stub("explode", new IOException("the disk is full"))), "explode")).isEqualTo(1);
            assertThat(err()).isEqualTo("orchard explode: the disk is full" + System.lineSeparator());
        }

        @Test
        void argumentsAfterTheNameReachTheCommand() {
            CommandLine echo = stub("echo", null);
            assertThat(run(List.of(echo), "echo", "a", "b")).isZero();
            assertThat(echo.<Stub>getCommand().received).containsExactly("a", "b");
        }

        @Test
        void twoCommandsWithOneNameAreRefused() {
            assertThatThrownBy(() -> Orchard.launcher(List.of(stub("twice", null), stub("twice", null)), print(out),
                    print(err)))
                    .isInstanceOf(CommandLine.DuplicateNameException.class)
                    .hasMessageContaining("'twice'");
        }

        @Test
        void commandNamesAreUnique() {
            assertThat(Orchard.commands(System.in, print(out), print(err))).extracting(CommandLine::getCommandName)
                    .doesNotHaveDuplicates().doesNotContain("help");
        }
    }

    private static CommandLine stub(String name, Exception failure) {
        return new CommandLine(new Stub(failure)).setCommandName(name);
    }

    /** A command that records its arguments and then fails with the given exception, if any. */
    @Command(description = "A stand-in")
    static final class Stub implements Callable<Integer> {

        @Parameters
        private List<String> received = List.of();

        private final Exception failure;

        Stub(Exception failure) {
            this.failure = failure;
        }

        @Override
        public Integer call() throws Exception {
            if (failure != null) {
                throw failure;
            }
            return 0;
        }
    }
}
