package io.orchard.agents.language;

import io.orchard.agents.language.Interpretation.NotUnderstood;
import io.orchard.agents.language.Interpretation.Understood;
import io.orchard.agents.language.Lexeme.Cat;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Understands instructions in simple English: "go to the castle", "grab the coconut on the table",
 * "Guppy, fetch me the small banana first, then explore". The result is an {@link Interpretation}:
 * a typed {@link Goal} with the agent's restatement, or a helpful answer that names the words it
 * did not know. The grammar and vocabulary are documented in {@code docs/instructions.md}.
 *
 * <p>Understanding works on phrasings rather than on a list of sentences: the sentence is
 * normalised (case, accents, punctuation, contractions), typos are corrected against the
 * vocabulary (one edit for words of 4 to 6 letters, two for longer ones, never when two known
 * words are as close), synonyms and inflections are reduced to one word each ("grab", "fetch",
 * "eat" are "collect"; "bananas" is "banana"), and a small grammar reads the clauses.
 *
 * <p>It never throws: any input, null, empty, very long or full of symbols, gives an
 * interpretation. Instances are immutable and safe to share between threads and agents.
 */
public final class InstructionInterpreter implements Interpreter {

    private static final Logger LOG = LoggerFactory.getLogger(InstructionInterpreter.class);

    /** Sentences longer than this are refused rather than read: instructions are short. */
    static final int MAX_CHARACTERS = 400;

    private static final int QUOTED_CHARACTERS = 60;

    private final Lexicon lexicon;

    /** An interpreter that knows the names of the paper's agents: Dwarf, Robot, Bunny, Guppy and Roadrunner. */
    public InstructionInterpreter() {
        this(List.of());
    }

    /**
     * An interpreter that also knows these agents' names, so that "follow alice" finds Alice even in
     * lower case, and "folow Alise" is corrected. A capitalised word it does not know is taken as a
     * name where a name can stand ("follow Zed", "Zed, stop") whether or not it was given here.
     *
     * @param agentNames the names of the other agents in the world, single words as they are
     *                   registered; names that are words of the vocabulary are ignored
     */
    public InstructionInterpreter(Collection<String> agentNames) {
        Objects.requireNonNull(agentNames, "agentNames");
        List<String> names = new ArrayList<>();
        for (String name : agentNames) {
            if (name != null && !name.isBlank()) {
                names.add(name);
            }
        }
        this.lexicon = Lexicon.withAgents(names);
    }

    /**
     * What this sentence asks for.
     *
     * @param sentence an instruction in English; may be null, empty or anything else
     * @return the goal with its restatement, or an answer that says what was not understood
     */
    @Override
    public Interpretation interpret(String sentence) {
        return interpret(sentence, Discourse.NONE);
    }

    /**
     * What this sentence asks for, said to an agent that spoke of or looked at these things last: "that
     * table" and "it" may mean one of them.
     *
     * @param sentence  an instruction in English; may be null, empty or anything else
     * @param discourse what the agent spoke about last; {@link Discourse#NONE} for nothing
     */
    @Override
    public Interpretation interpret(String sentence, Discourse discourse) {
        try {
            return understand(sentence, discourse == null ? Discourse.NONE : discourse);
        } catch (RuntimeException e) {
            LOG.warn("could not interpret '{}'", quote(sentence), e);
            return new NotUnderstood(Answers.GENERIC_FAILURE, List.of(), Optional.empty());
        }
    }

    /** {@link #interpret} without its safety net, so that tests see any defect. */
    Interpretation understand(String sentence) {
        return understand(sentence, Discourse.NONE);
    }

    private Interpretation understand(String sentence, Discourse discourse) {
        if (sentence == null || sentence.isBlank()) {
            return new NotUnderstood(Answers.EMPTY, List.of(), Optional.empty());
        }
        if (sentence.length() > MAX_CHARACTERS) {
            return new NotUnderstood(Answers.TOO_LONG, List.of(), Optional.empty());
        }
        List<Tokenizer.Token> tokens = Tokenizer.tokens(sentence);
        if (tokens.stream().noneMatch(token -> token.isWord() || token.type() == Tokenizer.Type.NUMBER)) {
            return new NotUnderstood(Answers.notUnderstood(quote(sentence), List.of(), Answers.CAN_DO), List.of(),
                    Optional.empty());
        }
        if (sentence.matches("(?s).*(^|[^\\p{L}\\p{N}-])-\\s*\\d.*")) {
            return new NotUnderstood(Answers.NEGATIVE, List.of(), Optional.empty());
        }
        Optional<Questions.Frame> question = Questions.read(tokens, lexicon);
        if (question.isPresent()) {
            Interpretation asked = asked(question.get(), sentence);
            if (asked != null) {
                return asked;
            }
        }
        Interpretation heard = command(tokens, sentence, discourse);
        if (heard instanceof NotUnderstood notUnderstood) {
            String language = Languages.other(tokens);
            if (language != null) {
                return new NotUnderstood(Answers.otherLanguage(language), notUnderstood.unknownWords(),
                        notUnderstood.addressee());
            }
        }
        return heard;
    }

    /** A question the agents answer, or null when its words do not make sense as one. */
    private Interpretation asked(Questions.Frame frame, String sentence) {
        Optional<String> addressee = Optional.ofNullable(frame.addressee());
        Reference about = null;
        if (!frame.about().isEmpty()) {
            List<Lexeme> lexemes = lexicon.read(frame.about());
            about = new Parser(lexicon).reference(lexemes);
            if (about == null) {
                List<String> unknown = lexemes.stream().filter(lexeme -> lexeme.is(Cat.UNKNOWN)).map(Lexeme::raw)
                        .distinct().toList();
                return unknown.isEmpty() ? null : new NotUnderstood(Answers.notUnderstood(quote(sentence), unknown,
                        Answers.CAN_DO), unknown, addressee);
            }
            if (frame.topic() == Ask.Topic.COLLECTED && about.equals(Reference.to(Reference.Kind.FRUIT))) {
                about = null; // "how many fruits": all of them
            }
        }
        Ask ask = new Ask(frame.topic(), about);
        return new Understood(ask, ask.restatement(), addressee);
    }

    /** The sentence read as a command. */
    private Interpretation command(List<Tokenizer.Token> tokens, String sentence, Discourse discourse) {
        List<Lexeme> lexemes = lexicon.read(tokens);
        Parser parser = new Parser(lexicon, discourse);
        Goal goal = null;
        Refusal refusal = null;
        try {
            goal = parser.parse(lexemes);
        } catch (Refusal r) {
            refusal = r;
        }
        Optional<String> addressee = Optional.ofNullable(parser.addressee());
        boolean anyUnknown = lexemes.stream().anyMatch(lexeme -> unknown(lexeme, parser));
        if (refusal == null && !anyUnknown) {
            return new Understood(goal, goal.restatement(), addressee);
        }
        String hint = refusal == null || refusal.hint() == null ? Answers.CAN_DO : refusal.hint();
        if (refusal != null && refusal.answer() != null && !anyUnknown) {
            return new NotUnderstood(refusal.answer(), List.of(), addressee);
        }
        // a word taken for a known one did not lead to an understanding either: name it too
        Set<String> named = new LinkedHashSet<>();
        for (Lexeme lexeme : lexemes) {
            if (unknown(lexeme, parser)) {
                named.add(lexeme.raw());
            } else if (lexeme.corrected() != null) {
                named.add(lexeme.corrected());
            }
        }
        List<String> unknown = List.copyOf(named);
        return new NotUnderstood(Answers.notUnderstood(quote(sentence), unknown, hint), unknown, addressee);
    }

    private static boolean unknown(Lexeme lexeme, Parser parser) {
        return lexeme.is(Cat.UNKNOWN) && !parser.namesTaken().contains(lexeme.position());
    }

    /** The sentence as it can be quoted in an answer: one line, printable, not too long. */
    static String quote(String sentence) {
        if (sentence == null) {
            return "";
        }
        StringBuilder text = new StringBuilder();
        sentence.codePoints().forEach(c -> {
            if (Character.isWhitespace(c) || Character.isISOControl(c)) {
                if (text.length() > 0 && text.charAt(text.length() - 1) != ' ') {
                    text.append(' ');
                }
            } else if (Character.getType(c) != Character.FORMAT && Character.getType(c) != Character.UNASSIGNED
                    && Character.getType(c) != Character.PRIVATE_USE && Character.getType(c) != Character.SURROGATE) {
                text.appendCodePoint(c);
            }
        });
        String quoted = text.toString().strip();
        if (quoted.codePointCount(0, quoted.length()) > QUOTED_CHARACTERS) {
            quoted = quoted.substring(0, quoted.offsetByCodePoints(0, QUOTED_CHARACTERS)).strip() + "...";
        }
        return quoted;
    }
}
