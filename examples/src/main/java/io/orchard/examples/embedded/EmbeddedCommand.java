package io.orchard.examples.embedded;

import io.orchard.examples.OptionsCommand;
import io.orchard.protocol.cli.Options;
import java.io.PrintStream;
import java.util.List;

/** {@code ./orchard embedded [--seed N] [--time-limit SECONDS]}: runs {@link EmbeddedGame}. */
public final class EmbeddedCommand extends OptionsCommand {

    private static final Options OPTIONS = new Options("orchard embedded",
            "Runs the embedding example (io.orchard.examples.embedded.EmbeddedGame): a world server in this JVM"
                    + "\non a free port, Dwarf and Robot on threads of the same JVM in lockstep, the game's events"
                    + "\nas they happen, and the ranking.")
            .value("seed", "N", "seed of the world", "1998")
            .value("time-limit", "SECONDS", "length of the game in simulated seconds", "60");

    /** The {@code ./orchard embedded} command. */
    public EmbeddedCommand() {
        super("embedded", "run the embedding example: a server and two agents in one JVM, their events, the ranking",
                OPTIONS);
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws Exception {
        Options.Parsed options = OPTIONS.parse(args);
        EmbeddedGame.play(options.longValue("seed", Long.MIN_VALUE, Long.MAX_VALUE),
                options.number("time-limit", 1, 3600), out);
        return 0;
    }
}
