package io.orchard.examples.schema;

import io.orchard.protocol.ProtocolVersion;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code ./orchard protocol-schema [--out FILE]}: prints the {@link ProtocolSchema}, or writes it to
 * a file. {@code ./orchard protocol-schema --out docs/protocol.schema.json} refreshes the copy in the
 * repository after a message changes.
 */
@Command(name = "protocol-schema", abbreviateSynopsis = true, sortOptions = false,
        description = {"Print the JSON Schema of every protocol message", "",
            "It prints the JSON Schema (draft 2020-12) of every message of the Orchard protocol, version "
                    + ProtocolVersion.CURRENT + ": one \"oneOf\" branch per message type, the values they carry "
                    + "under \"$defs\"."},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n")
public final class ProtocolSchemaCommand implements Callable<Integer> {

    @Option(names = "--out", paramLabel = "FILE", description = "Write the schema to FILE instead of standard output")
    private String file;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    @Spec
    private CommandSpec spec;

    private final PrintStream out;

    /** The {@code ./orchard protocol-schema} command, printing to {@code out}. */
    public ProtocolSchemaCommand(PrintStream out) {
        this.out = out;
    }

    @Override
    public Integer call() throws IOException {
        if (this.file != null && this.file.isBlank()) {
            throw new ParameterException(spec.commandLine(), "invalid value for option '--out': '" + this.file
                    + "' is blank (expected a file name)");
        }
        Path file = this.file == null ? null : Path.of(this.file);
        String schema = ProtocolSchema.json();
        if (file == null) {
            out.print(schema);
            out.flush();
            return 0;
        }
        Path directory = file.toAbsolutePath().getParent();
        if (directory != null && !Files.isDirectory(directory)) {
            throw new IOException("cannot write " + file + ": directory " + directory + " does not exist");
        }
        try {
            Files.writeString(file, schema, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IOException("cannot write " + file + " (" + e.getClass().getSimpleName() + ": "
                    + e.getMessage() + ")", e);
        }
        return 0;
    }
}
