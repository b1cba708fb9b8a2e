package io.orchard.examples;

import io.orchard.agents.cli.LanguageModelOptions;
import io.orchard.agents.cli.LanguageOption;
import io.orchard.agents.language.Ask;
import io.orchard.agents.language.GoalJson;
import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.Interpretation;
import io.orchard.agents.language.Interpreter;
import io.orchard.agents.language.Language;
import io.orchard.agents.language.LanguageModel;
import io.orchard.agents.language.LanguageModelInterpreter;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code ./orchard parse [--agents NAMES] [--language CODE] [--notation] SENTENCE...}: shows what an
 * agent makes of an instruction in English (or German, with {@code --language de}), as {@link InstructionInterpreter} understands it: the goal as JSON and
 * the agent's one-line restatement (and, for a question, which question it is), or the agent's answer
 * when it does not understand. Either way
 * the exit status is 0; only a command line without a sentence is a usage error.
 */
@Command(name = "parse", abbreviateSynopsis = true, sortOptions = false,
        description = {"Show how an agent understands an instruction in English", "",
            "It prints what an agent makes of an instruction in English: the goal as JSON and the agent's one-line "
                    + "restatement, or, when it does not understand, its answer, which names the words it does not "
                    + "know. The sentence may be one argument or several words; everything after -- is taken as the "
                    + "sentence. The grammar, the vocabulary and the forms of goals are described in "
                    + "docs/instructions.md. With --language de, German is understood too, and the restatement or "
                    + "answer is in the language of the sentence. With --language-model, a sentence the grammar does "
                    + "not understand is given to that model, as an agent with the same options does."},
        descriptionHeading = "%n", parameterListHeading = "%nArguments:%n", optionListHeading = "%nOptions:%n",
        footerHeading = "%nExample:%n", footer = "  ./orchard parse \"get the nearest banana on a table\"")
public final class ParseCommand implements Callable<Integer> {

    @Parameters(paramLabel = "SENTENCE", arity = "0..*", description = "The instruction, in one or more words")
    private List<String> words = new ArrayList<>();

    @Option(names = "--agents", paramLabel = "NAMES",
            description = "Other agents' names to know, separated by commas; Dwarf, Robot, Bunny, Guppy and Roadrunner "
                    + "are always known")
    private List<String> agentLists = new ArrayList<>();

    @Mixin
    private LanguageOption language;

    @Mixin
    private LanguageModelOptions languageModel;

    @Option(names = "--notation", description = "Print the goal in the compact notation instead of JSON")
    private boolean notation;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help and exit")
    private boolean help;

    @Spec
    private CommandSpec spec;

    private final PrintStream out;

    /** The {@code ./orchard parse} command, printing to {@code out}. */
    public ParseCommand(PrintStream out) {
        this.out = out;
    }

    @Override
    public Integer call() {
        List<String> agents = new ArrayList<>();
        for (String list : agentLists) {
            agents.addAll(names(list));
        }
        if (words.isEmpty()) {
            throw new ParameterException(spec.commandLine(),
                    "expected a sentence, for example: ./orchard parse \"go to the castle\"");
        }
        Interpreter interpreter = new InstructionInterpreter(agents, language.language());
        LanguageModel model = languageModel.model();
        if (model != null) {
            interpreter = new LanguageModelInterpreter(interpreter, model);
        }
        Interpretation interpretation = interpreter.interpret(String.join(" ", words));
        interpretation.addressee().ifPresent(name -> out.println("Addressed to " + name + "."));
        if (interpretation instanceof Interpretation.Understood understood) {
            out.println(notation ? understood.goal().notation() : GoalJson.writePretty(understood.goal()));
            if (understood.goal() instanceof Ask ask) {
                out.println("A question (" + ask.topic().wireName() + "): the agent answers it from what it knows "
                        + "and goes on with what it was doing.");
            }
            if (understood.language() != Language.ENGLISH) {
                out.println("Read as " + understood.language().englishName() + ".");
            }
            out.println(understood.restatement());
        } else if (interpretation instanceof Interpretation.NotUnderstood notUnderstood) {
            out.println(notUnderstood.answer());
        }
        out.flush();
        return 0;
    }

    private List<String> names(String list) {
        List<String> names = Arrays.stream(list.split(",")).map(String::strip).filter(name -> !name.isEmpty())
                .toList();
        if (names.isEmpty()) {
            throw new ParameterException(spec.commandLine(), "invalid value for option '--agents': '" + list
                    + "' names no agent (expected names separated by commas, such as Alice,Bob)");
        }
        return names;
    }
}
