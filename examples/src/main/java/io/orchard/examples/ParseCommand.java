package io.orchard.examples;

import io.orchard.agents.language.GoalJson;
import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.Interpretation;
import io.orchard.protocol.cli.UsageException;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * {@code ./orchard parse [--agents NAMES] [--notation] SENTENCE...}: shows what an agent makes of an
 * instruction in English, as {@link InstructionInterpreter} understands it: the goal as JSON and
 * the agent's one-line restatement, or the agent's answer when it does not understand. Either way
 * the exit status is 0; only a command line without a sentence is a usage error.
 */
public final class ParseCommand implements Command {

    private static final String AGENTS = "--agents";
    private static final String NOTATION = "--notation";

    @Override
    public String name() {
        return "parse";
    }

    @Override
    public String summary() {
        return "Show how an agent understands an instruction in English";
    }

    @Override
    public String help() {
        return """
                Usage: ./orchard parse [--agents NAMES] [--notation] SENTENCE...

                Shows what an agent makes of an instruction in English: the goal as JSON and the
                agent's one-line restatement, or, when it does not understand, its answer, which
                names the words it does not know. The sentence may be one argument or several
                words; everything after -- is taken as the sentence. The grammar, the vocabulary
                and the forms of goals are described in docs/instructions.md.

                Options:
                  --agents NAMES  Other agents' names to know, separated by commas; Dwarf, Robot,
                                  Bunny, Guppy and Roadrunner are always known
                  --notation      Print the goal in the compact notation instead of JSON
                  --help          Show this help

                Example:
                  ./orchard parse "get the nearest banana on a table"
                """;
    }

    @Override
    public int run(List<String> args, PrintStream out, PrintStream err) throws UsageException {
        List<String> agents = new ArrayList<>();
        List<String> words = new ArrayList<>();
        boolean notation = false;
        boolean sentenceOnly = false;
        for (int i = 0; i < args.size(); i++) {
            String arg = args.get(i);
            if (sentenceOnly || !arg.startsWith("--")) {
                words.add(arg);
            } else if (arg.equals("--")) {
                sentenceOnly = true;
            } else if (arg.equals(NOTATION)) {
                notation = true;
            } else if (arg.equals(AGENTS) && i + 1 < args.size()) {
                agents.addAll(names(args.get(++i)));
            } else if (arg.startsWith(AGENTS + "=")) {
                agents.addAll(names(arg.substring(AGENTS.length() + 1)));
            } else if (arg.equals(AGENTS)) {
                throw new UsageException(AGENTS + " needs names after it, for example " + AGENTS + " Alice,Bob");
            } else {
                throw new UsageException("unexpected option '" + arg + "'; expected " + AGENTS + " NAMES, "
                        + NOTATION + ", --help or a sentence");
            }
        }
        if (words.isEmpty()) {
            throw new UsageException("expected a sentence, for example: ./orchard parse \"go to the castle\"");
        }
        Interpretation interpretation = new InstructionInterpreter(agents).interpret(String.join(" ", words));
        interpretation.addressee().ifPresent(name -> out.println("Addressed to " + name + "."));
        if (interpretation instanceof Interpretation.Understood understood) {
            out.println(notation ? understood.goal().notation() : GoalJson.writePretty(understood.goal()));
            out.println(understood.restatement());
        } else if (interpretation instanceof Interpretation.NotUnderstood notUnderstood) {
            out.println(notUnderstood.answer());
        }
        out.flush();
        return 0;
    }

    private static List<String> names(String list) throws UsageException {
        List<String> names = Arrays.stream(list.split(",")).map(String::strip).filter(name -> !name.isEmpty())
                .toList();
        if (names.isEmpty()) {
            throw new UsageException(AGENTS + " needs names separated by commas, was '" + list + "'");
        }
        return names;
    }
}
