package io.orchard.examples;

import io.orchard.protocol.cli.Options;

/**
 * A {@link Command} whose help is its {@link Options}' help: the name, the one-line summary and
 * the options are given once, and the command only says how it runs.
 */
public abstract class OptionsCommand implements Command {

    private final String name;
    private final String summary;
    private final Options options;

    /**
     * @param name    the word that selects the command, e.g. {@code demo}
     * @param summary one line for the launcher's list of commands, without a full stop
     * @param options the command's options; their help is the command's
     */
    protected OptionsCommand(String name, String summary, Options options) {
        this.name = name;
        this.summary = summary;
        this.options = options;
    }

    @Override
    public final String name() {
        return name;
    }

    @Override
    public final String summary() {
        return summary;
    }

    @Override
    public final String help() {
        return options.help();
    }
}
