package io.orchard.examples;

import java.io.PrintStream;
import java.util.concurrent.Callable;
import picocli.AutoComplete;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code ./orchard completion}: prints a bash completion script for the launcher, made by picocli
 * from its commands and their options, so that it never lags behind them.
 */
@Command(name = "completion", abbreviateSynopsis = true,
        description = {"Print a bash completion script for orchard", "",
            "The script completes the commands, their options and the values of some (such as --clock), for "
                    + "./orchard and for an orchard on the PATH. Load it into the current shell (bash, or zsh with "
                    + "bashcompinit) with:", "",
            "  source <(./orchard completion)", "",
            "or save it for every new shell where bash-completion looks:", "",
            "  ./orchard completion > ~/.local/share/bash-completion/completions/orchard"},
        descriptionHeading = "%n", optionListHeading = "%nOptions:%n")
final class CompletionCommand implements Callable<Integer> {

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    @Spec
    private CommandSpec spec;

    private final PrintStream out;

    CompletionCommand(PrintStream out) {
        this.out = out;
    }

    @Override
    public Integer call() {
        out.print(AutoComplete.bash(spec.root().name(), spec.root().commandLine()));
        out.flush();
        return 0;
    }
}
