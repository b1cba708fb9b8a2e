package io.orchard.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.Callable;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

class CommandLineErrorsTest {

    private final ByteArrayOutputStream err = new ByteArrayOutputStream();

    @Command(name = "orchard thing")
    static final class Thing implements Callable<Integer> {

        @Option(names = "--port", converter = Port.class)
        int port = 7557;

        @Option(names = "--fail")
        String fail;

        @Override
        public Integer call() throws Exception {
            if (fail == null) {
                return 0;
            }
            throw fail.equals("defect") ? new IllegalStateException("a defect") : new IOException("no server");
        }
    }

    private int run(String... args) {
        return CommandLineErrors.execute(new CommandLine(new Thing()), List.of(args),
                new PrintStream(err, true, StandardCharsets.UTF_8));
    }

    private String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    @Test
    void aRightCommandLineRuns() {
        assertThat(run("--port", "80")).isZero();
        assertThat(err()).isEmpty();
    }

    @Test
    void aBadValueNamesTheCommandTheOptionAndWhatWasExpectedAndExitsWithTwo() {
        assertThat(run("--port", "0")).isEqualTo(CommandLineErrors.USAGE).isEqualTo(2);
        assertThat(err()).startsWith("orchard thing: invalid value for option '--port': '0' is out of range "
                + "(expected a port 1-65535)").contains("Run ./orchard thing --help for its options.");
    }

    @Test
    void anUnexpectedArgumentSaysThatOptionsStartWithTwoDashes() {
        assertThat(run("port", "80")).isEqualTo(2);
        assertThat(err()).startsWith("orchard thing: unexpected arguments 'port', '80' (options start with --)");
    }

    @Test
    void anUnknownOptionIsNamed() {
        assertThat(run("--prot")).isEqualTo(2);
        assertThat(err()).isEqualTo("orchard thing: unknown option: '--prot'" + System.lineSeparator()
                + "Run ./orchard thing --help for its options." + System.lineSeparator());
    }

    @Test
    void aFailureSaysWhyAndExitsWithOne() {
        assertThat(run("--fail", "io")).isEqualTo(CommandLineErrors.FAILED).isEqualTo(1);
        assertThat(err()).isEqualTo("orchard thing: no server" + System.lineSeparator());
    }

    @Test
    void aDefectAlsoPrintsItsStackTrace() {
        assertThat(run("--fail", "defect")).isEqualTo(1);
        assertThat(err()).startsWith("orchard thing: a defect").contains("java.lang.IllegalStateException: a defect",
                "at io.orchard.cli.CommandLineErrorsTest$Thing.call");
    }
}
