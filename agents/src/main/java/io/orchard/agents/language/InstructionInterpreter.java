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

    /** The vocabularies of the languages understood, the agent's own first. */
    private final List<Lexicon> lexicons;

    /** An interpreter that knows the names of the paper's agents: Dwarf, Robot, Bunny, Guppy and Roadrunner. */
    public InstructionInterpreter() {
        this(List.of());
    }

    /**
     * An interpreter of English and, when {@code language} is {@link Language#GERMAN}, of German too:
     * each sentence is read in the language it is in (the agent's own when the words do not tell), and
     * answered in it.
     *
     * @param agentNames the names of the other agents in the world, as for {@link #InstructionInterpreter(Collection)}
     * @param language   the agent's own language, understood besides English
     */
    public InstructionInterpreter(Collection<String> agentNames, Language language) {
        Objects.requireNonNull(language, "language");
        List<String> names = names(agentNames);
        List<Lexicon> understood = new ArrayList<>();
        understood.add(Lexicon.withAgents(names, language));
        if (language != Language.ENGLISH) {
            understood.add(Lexicon.withAgents(names, Language.ENGLISH));
        }
        this.lexicons = List.copyOf(understood);
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
        this(agentNames, Language.ENGLISH);
    }

    private static List<String> names(Collection<String> agentNames) {
        Objects.requireNonNull(agentNames, "agentNames");
        List<String> names = new ArrayList<>();
        for (String name : agentNames) {
            if (name != null && !name.isBlank()) {
                names.add(name);
            }
        }
        return names;
    }

    /** The languages this interpreter understands, the agent's own first. */
    public List<Language> languages() {
        return lexicons.stream().map(Lexicon::language).toList();
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
            Language own = lexicons.get(0).language();
            return new NotUnderstood(Answers.of(own).GENERIC_FAILURE, List.of(), Optional.empty(), own);
        }
    }

    /** {@link #interpret} without its safety net, so that tests see any defect. */
    Interpretation understand(String sentence) {
        return understand(sentence, Discourse.NONE);
    }

    private Interpretation understand(String sentence, Discourse discourse) {
        List<Tokenizer.Token> tokens = sentence == null ? List.of() : Tokenizer.tokens(sentence);
        List<Lexicon> order = new ArrayList<>(lexicons);
        if (order.size() > 1 && order.get(1).own(tokens) > order.get(0).own(tokens)) {
            order.add(0, order.remove(1)); // the words are the other language's: read it in that one first
        }
        Interpretation first = null;
        for (Lexicon lexicon : order) {
            Interpretation heard;
            try {
                heard = understand(sentence, tokens, discourse, lexicon);
            } catch (RuntimeException e) {
                if (order.size() == 1) {
                    throw e;
                }
                // a defect in one language's reading must not keep the other from reading the sentence
                LOG.warn("could not interpret '{}' in {}", quote(sentence), lexicon.language().englishName(), e);
                heard = new NotUnderstood(Answers.of(lexicon.language()).GENERIC_FAILURE, List.of(), Optional.empty(),
                        lexicon.language());
            }
            if (heard instanceof Understood) {
                return heard;
            }
            if (first == null) {
                first = heard;
            }
        }
        if (first instanceof NotUnderstood notUnderstood) {
            String language = Languages.other(tokens, languages());
            if (language != null) {
                Answers answers = Answers.of(notUnderstood.language());
                return new NotUnderstood(answers.otherLanguage(language, languages()), notUnderstood.unknownWords(),
                        notUnderstood.addressee(), notUnderstood.language());
            }
        }
        return first;
    }

    /** The sentence read in one language. */
    private Interpretation understand(String sentence, List<Tokenizer.Token> written, Discourse discourse,
                                      Lexicon lexicon) {
        Language language = lexicon.language();
        Answers answers = Answers.of(language);
        if (sentence == null || sentence.isBlank()) {
            return new NotUnderstood(answers.EMPTY, List.of(), Optional.empty(), language);
        }
        if (sentence.length() > MAX_CHARACTERS) {
            return new NotUnderstood(answers.TOO_LONG, List.of(), Optional.empty(), language);
        }
        List<Tokenizer.Token> tokens = language == Language.GERMAN
                ? German.tokens(Tokenizer.tokens(sentence, Language.GERMAN)) : written;
        if (tokens.stream().noneMatch(token -> token.isWord() || token.type() == Tokenizer.Type.NUMBER)) {
            return new NotUnderstood(answers.notUnderstood(quote(sentence), List.of(), answers.CAN_DO), List.of(),
                    Optional.empty(), language);
        }
        if (sentence.matches("(?s).*(^|[^\\p{L}\\p{N}-])-\\s*\\d.*")) {
            return new NotUnderstood(answers.NEGATIVE, List.of(), Optional.empty(), language);
        }
        Optional<Questions.Frame> question = Questions.read(tokens, lexicon);
        if (question.isPresent()) {
            Interpretation asked = asked(question.get(), sentence, lexicon);
            if (asked != null) {
                return asked;
            }
        }
        return command(tokens, sentence, discourse, lexicon);
    }

    /** A question the agents answer, or null when its words do not make sense as one. */
    private Interpretation asked(Questions.Frame frame, String sentence, Lexicon lexicon) {
        Optional<String> addressee = Optional.ofNullable(frame.addressee());
        Language language = lexicon.language();
        Answers answers = Answers.of(language);
        Reference about = null;
        if (!frame.about().isEmpty()) {
            List<Lexeme> lexemes = lexicon.read(frame.about());
            about = new Parser(lexicon, Discourse.NONE).reference(lexemes);
            if (about == null) {
                List<String> unknown = lexemes.stream().filter(lexeme -> lexeme.is(Cat.UNKNOWN)).map(Lexeme::raw)
                        .distinct().toList();
                return unknown.isEmpty() ? null : new NotUnderstood(answers.notUnderstood(quote(sentence), unknown,
                        answers.CAN_DO), unknown, addressee, language);
            }
            if (frame.topic() == Ask.Topic.COLLECTED && about.equals(Reference.to(Reference.Kind.FRUIT))) {
                about = null; // "how many fruits": all of them
            }
        }
        Ask ask = new Ask(frame.topic(), about);
        return new Understood(ask, ask.restatement(language), addressee, language);
    }

    /** The sentence read as a command. */
    private Interpretation command(List<Tokenizer.Token> tokens, String sentence, Discourse discourse,
                                   Lexicon lexicon) {
        Language language = lexicon.language();
        Answers answers = Answers.of(language);
        List<Lexeme> read = lexicon.read(tokens);
        List<Lexeme> lexemes = language == Language.GERMAN ? German.lexemes(read) : read;
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
            return new Understood(goal, goal.restatement(language), addressee, language);
        }
        String hint = refusal == null || refusal.hint() == null ? answers.CAN_DO : refusal.hint();
        if (refusal != null && refusal.answer() != null && !anyUnknown) {
            return new NotUnderstood(refusal.answer(), List.of(), addressee, language);
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
        return new NotUnderstood(answers.notUnderstood(quote(sentence), unknown, hint), unknown, addressee, language);
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
