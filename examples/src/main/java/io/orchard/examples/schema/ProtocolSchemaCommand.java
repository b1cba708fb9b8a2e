package io.orchard.examples.schema;

import io.orchard.examples.Command;
import io.orchard.protocol.cli.UsageException;
import io.orchard.protocol.ProtocolVersion;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * {@code ./orchard protocol-schema [--out FILE]}: prints the {@link ProtocolSchema}, or writes it to
 * a file. {@code ./orchard protocol-schema --out docs/protocol.schema.json} refreshes the copy in the
 * repository after a message changes.
 */
public final class ProtocolSchemaCommand implements Command {

    private static final String OUT = "--out";

    @Override
    public String name() {
        return "protocol-schema";
    }

    @Override
    public String summary() {
        return "Print the JSON Schema of every protocol message";
    }

    @Override
    public String help() {
        return """
                Usage: ./orchard protocol-schema [--out FILE]

                Prints the JSON Schema (draft 2020-12) of every message of the Orchard protocol,
                version %d: one "oneOf" branch per message type, the values they carry under "$defs".

                Options:
                  --out FILE  Write the schema to FILE instead of standard output
                  --help      Show this help
                """.formatted(ProtocolVersion.CURRENT);
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException, IOException {
        Path file = null;
        for (int i = 0; i < args.size(); i++) {
            String arg = args.get(i);
            if (arg.equals(OUT) && i + 1 < args.size()) {
                file = outFile(args.get(++i));
            } else if (arg.startsWith(OUT + "=")) {
                file = outFile(arg.substring(OUT.length() + 1));
            } else if (arg.equals(OUT)) {
                throw new UsageException(OUT + " needs a file name after it");
            } else {
                throw new UsageException("unexpected argument '" + arg + "'; expected " + OUT + " FILE or --help");
            }
        }
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

    private static Path outFile(String name) throws UsageException {
        if (name.isBlank()) {
            throw new UsageException(OUT + " needs a file name, was '" + name + "'");
        }
        return Path.of(name);
    }
}
