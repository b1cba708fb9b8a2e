package io.orchard.agents.language;

import static io.orchard.agents.language.Lexeme.Cat.AGAIN;
import static io.orchard.agents.language.Lexeme.Cat.COND;
import static io.orchard.agents.language.Lexeme.Cat.DET;
import static io.orchard.agents.language.Lexeme.Cat.DIR;
import static io.orchard.agents.language.Lexeme.Cat.HERE;
import static io.orchard.agents.language.Lexeme.Cat.LASTING;
import static io.orchard.agents.language.Lexeme.Cat.ME;
import static io.orchard.agents.language.Lexeme.Cat.NAME;
import static io.orchard.agents.language.Lexeme.Cat.NEG;
import static io.orchard.agents.language.Lexeme.Cat.NOUN;
import static io.orchard.agents.language.Lexeme.Cat.NUMBER;
import static io.orchard.agents.language.Lexeme.Cat.ONLY;
import static io.orchard.agents.language.Lexeme.Cat.PERMIT;
import static io.orchard.agents.language.Lexeme.Cat.PREP;
import static io.orchard.agents.language.Lexeme.Cat.PRON;
import static io.orchard.agents.language.Lexeme.Cat.PUNCT;
import static io.orchard.agents.language.Lexeme.Cat.QUANT;
import static io.orchard.agents.language.Lexeme.Cat.RULE;
import static io.orchard.agents.language.Lexeme.Cat.SIDE;
import static io.orchard.agents.language.Lexeme.Cat.UNIT;
import static io.orchard.agents.language.Lexeme.Cat.UNKNOWN;
import static io.orchard.agents.language.Lexeme.Cat.VERB;

import io.orchard.agents.language.Clauses.Segment;
import io.orchard.agents.language.NounPhrases.Phrase;
import io.orchard.agents.language.Place.Relation;
import io.orchard.agents.language.Reference.Kind;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * The grammar: turns the lexemes of one sentence into a goal, or throws a {@link Refusal}.
 *
 * <p>The sentence's address is taken off ("Guppy, ..."), its {@link Clauses clauses} are split and
 * ordered, and each clause is read as a command: a verb, then what its verb class expects (a
 * destination, fruit, a direction, an agent, a duration), with {@link NounPhrases noun phrases}
 * for the things it refers to. A parser keeps the {@link ParseContext state} of one sentence; make
 * a new one per sentence.
 */
final class Parser {

    private static final double MAX_COUNT = 1000;

    private final Lexicon lexicon;
    private final ParseContext context = new ParseContext();
    private final NounPhrases phrases = new NounPhrases(context);

    /** A parser for one sentence, in the lexicon's language, said to an agent that spoke of these things last. */
    Parser(Lexicon lexicon, Discourse discourse) {
        this.lexicon = lexicon;
        this.context.discourse = discourse;
        this.context.answers = Answers.of(lexicon.language());
        this.context.hint = context.answers.CAN_DO;
        this.context.question = context.answers.WHAT_PICK;
    }

    /** The positions of unknown words taken as agents' names. */
    Set<Integer> namesTaken() {
        return context.namesTaken;
    }

    /** The agent the sentence was addressed to, or null; known even when parsing failed. */
    String addressee() {
        return context.addressee;
    }

    /** The goal of this sentence. */
    Goal parse(List<Lexeme> lexemes) {
        List<Lexeme> rest = new ArrayList<>(lexemes);
        takeLeadingAddress(rest);
        takeMarkers(rest);
        List<Segment> segments = takeAddressSegments(Clauses.split(rest));
        if (segments.isEmpty()) {
            throw Refusal.answer(context.addressee != null ? context.answers.YES : context.answers.EMPTY);
        }
        segments = Clauses.withoutBareMotion(Clauses.ordered(segments));
        Goal goal = goals(segments);
        if (context.permit && context.again) {
            return lifted(goal); // "you can go near the river again"
        }
        if (context.lasting && !standing(goal)) {
            throw Refusal.answer(context.answers.LASTING);
        }
        return goal;
    }

    /** "from now on", "again", "you can": said anywhere, they are about the whole sentence. */
    private void takeMarkers(List<Lexeme> rest) {
        for (Lexeme lexeme : rest) {
            context.lasting |= lexeme.is(LASTING);
            context.again |= lexeme.is(AGAIN);
            context.permit |= lexeme.is(PERMIT);
        }
        rest.removeIf(lexeme -> lexeme.is(LASTING) || lexeme.is(AGAIN) || lexeme.is(PERMIT));
    }

    /** The goals of these clauses, in order; a condition takes the clauses after it as what it does. */
    private Goal goals(List<Segment> segments) {
        List<Goal> goals = new ArrayList<>();
        List<Lexeme> prefix = List.of();
        for (int i = 0; i < segments.size(); i++) {
            List<Lexeme> tokens = segments.get(i).tokens();
            Lexeme first = tokens.get(0);
            if (first.is(COND)) {
                return condition(goals, segments, i);
            }
            boolean unknownVerb = first.is(UNKNOWN) && !first.capitalised();
            if (!first.is(VERB) && !first.is(NEG) && !first.is(ONLY) && !unknownVerb && !prefix.isEmpty()) {
                // "then to the bridge" borrows only the verb of "walk to the castle"
                List<Lexeme> borrowed = new ArrayList<>(first.is(PREP) ? prefix.subList(0, 1) : prefix);
                borrowed.addAll(tokens);
                tokens = borrowed;
            }
            prefix = Clauses.prefixOf(tokens);
            context.hint = context.answers.CAN_DO;
            context.question = context.answers.WHAT_PICK;
            Goal goal = clause(tokens, i == segments.size() - 1);
            if (goal != null) {
                goals.add(goal);
            }
        }
        if (goals.isEmpty()) {
            throw Refusal.answer(context.answers.EMPTY);
        }
        return Sequence.of(goals);
    }

    /**
     * "when you see a banana, take it" (what it does after), or "take the bananas when you see them"
     * (what it does before): a {@link WhenSee}. Other conditions ("when you are tired") are refused.
     */
    private Goal condition(List<Goal> before, List<Segment> segments, int at) {
        List<Lexeme> tokens = segments.get(at).tokens();
        if (!tokens.get(0).is(COND, "when-see")) {
            throw Refusal.hint(context.answers.CAN_WATCH); // "when you are tired": not something it sees
        }
        context.hint = context.answers.CAN_WATCH;
        context.question = context.answers.WHAT_WATCH;
        Cursor c = new Cursor(tokens.subList(1, tokens.size()));
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.WHAT_WATCH);
        }
        Phrase seen = phrases.phrase(c, true);
        if (seen == null || seen.ref() == null || seen.ref().kind() == Kind.PLACE || seen.ref().kind() == Kind.START) {
            throw Refusal.hint(context.answers.CAN_WATCH);
        }
        Reference what = seen.ref().withDistance(null).withSize(seen.ref().size() == Reference.Size.LARGEST
                || seen.ref().size() == Reference.Size.SMALLEST ? null : seen.ref().size());
        if (!before.isEmpty()) {
            if (!c.atEnd() || at + 1 < segments.size()) {
                throw Refusal.hint(context.answers.CAN_WATCH);
            }
            return watching(what, Sequence.of(before));
        }
        context.antecedent = what;
        List<Segment> rest = new ArrayList<>();
        if (!c.atEnd()) {
            rest.add(new Segment(List.copyOf(c.rest()), false, Clauses.Marker.NONE));
        }
        rest.addAll(segments.subList(at + 1, segments.size()));
        if (rest.isEmpty()) {
            throw Refusal.answer(context.answers.whatWhenSeen(context.answers.noun(what, false)));
        }
        return watching(what, goals(rest));
    }

    private WhenSee watching(Reference what, Goal then) {
        for (Goal step : then instanceof Sequence sequence ? sequence.steps() : List.of(then)) {
            if (step instanceof Rule || step instanceof Lift || step instanceof Ask || step instanceof CarryOn) {
                throw Refusal.answer(context.answers.CONDITIONS);
            }
        }
        return new WhenSee(what, then);
    }

    /** Whether every step of the goal is a rule or lifts one. */
    private boolean standing(Goal goal) {
        for (Goal step : goal instanceof Sequence sequence ? sequence.steps() : List.of(goal)) {
            if (!(step instanceof Rule || step instanceof Lift)) {
                return false;
            }
        }
        return true;
    }

    /** "you can go near the river again", "you may take coconuts again": the rule that forbade it, lifted. */
    private Goal lifted(Goal goal) {
        List<Goal> lifts = new ArrayList<>();
        for (Goal step : goal instanceof Sequence sequence ? sequence.steps() : List.of(goal)) {
            if (step instanceof Lift) {
                lifts.add(step);
                continue;
            }
            Rule rule = step instanceof Rule ? null : forbidding(step);
            if (rule instanceof Avoid avoid) {
                lifts.add(new Lift(avoid.area()));
            } else if (rule instanceof Leave leave) {
                lifts.add(new Lift(leave.what()));
            } else {
                throw Refusal.answer(context.answers.LIFT_WHAT);
            }
        }
        return Sequence.of(lifts);
    }

    /**
     * The rule that forbids doing this goal, as "don't" makes of it: "don't go near the river" keeps
     * the agent out of the area near the river, "don't eat the tomatoes" keeps it from tomatoes;
     * null for a goal no rule can forbid ("don't follow Guppy").
     */
    private Rule forbidding(Goal goal) {
        if (goal instanceof GoTo goTo) {
            Reference to = goTo.destination();
            if (to.isFruit() || to.kind() == Kind.START) {
                return null;
            }
            if (to.kind() == Kind.RIVER || to.kind() == Kind.AGENT) {
                return new Avoid(Reference.place(Place.of(Relation.NEAR, to))); // the river is where near it starts
            }
            return new Avoid(to);
        }
        if (goal instanceof Cross cross) {
            Reference landmark = cross.landmark();
            return new Avoid(landmark.kind() == Kind.RIVER ? Reference.place(Place.of(Relation.BEYOND, landmark))
                    : landmark);
        }
        if (goal instanceof Head head && head.distance() == null) {
            return new Avoid(Reference.place(Place.of(Relation.of(head.direction()), null)));
        }
        if (goal instanceof Explore explore && explore.area() != null && !explore.area().isFruit()) {
            return new Avoid(explore.area());
        }
        if (goal instanceof Collect collect) {
            return new Leave(collect.what());
        }
        return null;
    }

    /** The reference these words make as one noun phrase ("the nearest banana"); null when they make none. */
    Reference reference(List<Lexeme> lexemes) {
        Cursor c = new Cursor(lexemes);
        if (c.atEnd()) {
            return null;
        }
        try {
            Phrase phrase = phrases.phrase(c, true);
            return phrase == null || !c.atEnd() ? null : phrase.ref();
        } catch (Refusal r) {
            return null;
        }
    }

    // ---- the sentence ----

    /** "Guppy, stop", "Guppy stop", "Alice: stop". */
    private void takeLeadingAddress(List<Lexeme> rest) {
        if (rest.size() < 2) {
            return;
        }
        Lexeme first = rest.get(0);
        Lexeme second = rest.get(1);
        boolean named = first.is(NAME) || (first.is(UNKNOWN) && first.capitalised());
        if (!named) {
            return;
        }
        boolean comma = second.is(PUNCT) && !second.lemma().equals(".") && rest.size() > 2;
        if (comma || (first.is(NAME) && (second.is(VERB) || second.is(NEG)))) {
            context.addressee = first.is(NAME) ? first.lemma() : first.raw();
            if (first.is(UNKNOWN)) {
                context.namesTaken.add(first.position());
            }
            rest.remove(0);
            if (comma) {
                rest.remove(0);
            }
        }
    }

    /** Clauses that are only a name, not joined by "and": "stop, Guppy". */
    private List<Segment> takeAddressSegments(List<Segment> segments) {
        List<Segment> kept = new ArrayList<>();
        for (Segment segment : segments) {
            List<Lexeme> tokens = segment.tokens();
            if (tokens.size() == 1 && tokens.get(0).is(NAME) && !segment.andJoined()
                    && (context.addressee == null || context.addressee.equalsIgnoreCase(tokens.get(0).lemma()))) {
                context.addressee = tokens.get(0).lemma();
            } else {
                kept.add(segment);
            }
        }
        return kept;
    }

    /** The goal of one clause, or null when it adds nothing ("pick up a banana and eat it"). */
    private Goal clause(List<Lexeme> tokens, boolean last) {
        Cursor c = new Cursor(tokens);
        Goal goal = command(c);
        if (c.atEnd()) {
            return goal;
        }
        if (c.peekIs(PREP, "to") && c.peekAt(1) != null && c.peekAt(1).is(VERB)) {
            c.next();
            return both(goal, clause(c.rest(), last)); // "go to the table to pick up the banana"
        }
        if (c.peek().is(VERB)) {
            return both(goal, clause(c.rest(), last));
        }
        if (last && c.remaining() == 1 && c.peek().is(NAME)
                && (context.addressee == null || context.addressee.equalsIgnoreCase(c.peek().lemma()))) {
            context.addressee = c.next().lemma(); // "stop Guppy"
            return goal;
        }
        throw Refusal.hint(context.hint);
    }

    private Goal both(Goal first, Goal then) {
        if (first == null || then == null) {
            return first == null ? then : first;
        }
        return Sequence.of(first, then);
    }
    // ---- commands ----

    private Goal command(Cursor c) {
        Lexeme t = c.peek();
        if (t.is(NEG)) {
            c.next();
            return negated(c);
        }
        if (t.is(ONLY)) {
            c.next();
            return only(c);
        }
        if (t.is(COND)) {
            throw Refusal.answer(context.answers.CONDITIONS);
        }
        if (t.is(VERB)) {
            c.next();
            return verb(t.lemma(), c);
        }
        if (t.is(DIR)) {
            c.next();
            return new Head(NounPhrases.sector(t));
        }
        if (t.is(SIDE)) {
            return sideways(c, false);
        }
        if (t.is(HERE, "home")) {
            c.next();
            return new ComeBack();
        }
        int start = c.position();
        Phrase phrase = phrases.phrase(c, false);
        if (phrase != null && context.lasting && phrase.ref() != null && phrase.ref().isFruit()) {
            return new Only(phrase.ref()); // "just tomatoes from now on"
        }
        if (phrase != null) {
            throw Refusal.answer(context.answers.whatToDoWith(c.rawSince(start), phrase.ref()));
        }
        if (c.peek() != null && c.peek().is(RULE)) {
            throw Refusal.answer(context.answers.RULES_HOW);
        }
        throw Refusal.hint(context.answers.CAN_DO);
    }

    /**
     * After "don't", "never", "no more": a rule against doing it ("don't go near the river", "never go
     * into the forest", "don't eat the tomatoes", "no more coconuts"), or no rules at all ("no more
     * rules"). What no rule can forbid is refused.
     */
    private Goal negated(Cursor c) {
        context.hint = context.answers.CAN_RULE;
        while (c.peekIs(DET, "the") || c.peekIs(DET, "a")) {
            c.next();
        }
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.NEGATION);
        }
        if (c.peek().is(RULE)) {
            c.next();
            return Lift.all();
        }
        if (c.peek().is(VERB)) {
            Goal goal = command(c);
            Rule rule = forbidding(goal);
            if (rule == null) {
                throw Refusal.answer(context.answers.NEGATION);
            }
            return rule;
        }
        Phrase phrase = phrases.phrase(c, false);
        if (phrase != null && phrase.ref() != null && phrase.ref().isFruit()) {
            return new Leave(phrase.ref()); // "no more coconuts"
        }
        throw Refusal.answer(context.answers.NEGATION);
    }

    /** After "only": "only bananas (from now on)", "only collect bananas", "only the bananas on the tables". */
    private Goal only(Cursor c) {
        context.hint = context.answers.CAN_RULE;
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.ONLY_WHAT);
        }
        if (c.peek().is(VERB)) {
            Goal goal = command(c);
            if (goal instanceof Collect collect) {
                return collect.isAll() ? new Only(collect.what()) : collect; // "only pick up one banana"
            }
            if (goal instanceof Only) {
                return goal;
            }
            throw Refusal.answer(context.answers.ONLY_WHAT);
        }
        Phrase phrase = phrases.phrase(c, false);
        if (phrase != null && phrase.ref() != null && phrase.ref().isFruit()) {
            return new Only(phrase.ref());
        }
        throw Refusal.answer(context.answers.ONLY_WHAT);
    }

    private Goal verb(String lemma, Cursor c) {
        return switch (lemma) {
            case "go" -> go(c, false);
            case "come" -> go(c, true);
            case "return" -> back(c);
            case "cross" -> cross(c);
            case "collect", "pick", "take", "get" -> collect(c, lemma);
            case "turn" -> turn(c);
            case "face" -> face(c);
            case "look" -> look(c);
            case "find" -> lookFor(c);
            case "search" -> search(c);
            case "explore" -> explore(c);
            case "follow" -> follow(c);
            case "stop" -> stop(c);
            case "wait" -> waitHere(c);
            case "carry-on" -> carryOn(c);
            case "enter", "approach" -> goTo(c);
            case "keep", "start" -> keep(c);
            case "do" -> doVerb(c);
            case "use" -> use(c);
            case "leave" -> leave(c);
            case "avoid" -> avoid(c);
            case "forget" -> forget(c);
            case "lift" -> liftRules(c);
            default -> throw Refusal.hint(context.answers.CAN_DO);
        };
    }

    /** After go, walk, run, head, come, ... */
    private Goal go(Cursor c, boolean come) {
        context.hint = context.answers.CAN_GO;
        while (c.peekIs(PREP, "up") || c.peekIs(PREP, "down") || c.peekIs(PREP, "out") || c.peekIs(UNIT, "bit")
                || (c.peekIs(PREP, "over") && c.peekAt(1) != null && c.peekAt(1).is(PREP, "to"))
                || (c.peekIs(SIDE, "straight") && c.remaining() > 1 && !c.peekAt(1).is(SIDE))) {
            c.next();
        }
        if (c.atEnd()) {
            if (come) {
                return new ComeBack();
            }
            throw Refusal.answer(context.answers.WHERE);
        }
        Double first = distance(c);
        if (first != null) {
            if (c.atEnd()) {
                return new RelativeMove(RelativeMove.Direction.FORWARD, first); // "walk 10 metres": straight on
            }
            return walked(go(c, come), first); // "walk 5 metres north"
        }
        Lexeme t = c.peek();
        if (t.is(VERB)) {
            return command(c); // "go get the banana", "come see"
        }
        if (t.is(PREP, "to") && c.peekAt(1) != null && c.peekAt(1).is(VERB)) {
            c.next();
            return command(c); // "go to pick up a banana"
        }
        if (t.is(PREP, "back")) {
            c.next();
            return back(c);
        }
        if (t.is(HERE) || t.is(ME)) {
            c.next();
            return here(t, come);
        }
        if (t.is(PREP, "on") && c.remaining() == 1) {
            c.next();
            return new CarryOn(); // "go on"
        }
        if (t.is(SIDE, "ahead") && c.remaining() == 1) {
            c.next();
            return new CarryOn(); // "go ahead"
        }
        if (t.is(SIDE)) {
            return sideways(c, true);
        }
        if (t.is(DIR)) {
            c.next();
            return compassGoal(t, c);
        }
        if (t.isAny(PREP, "across", "over", "through")) {
            c.next();
            return crossing(c);
        }
        if (t.is(PREP, "beyond")) {
            c.next();
            return beyond(c);
        }
        if (t.isAny(PREP, "to", "in", "on", "at", "for")) {
            c.next(); // "head for the castle"
            Lexeme next = c.peek();
            if (next == null) {
                throw Refusal.answer(context.answers.WHERE);
            }
            if (next.is(PREP, "beyond")) {
                c.next();
                return beyond(c);
            }
            if (next.is(DIR)) {
                c.next();
                return compassGoal(next, c);
            }
            if (next.is(HERE) || next.is(ME)) {
                c.next();
                return here(next, come);
            }
            if (next.is(SIDE)) {
                return sideways(c, true);
            }
            if (NounPhrases.isRelation(next)) {
                return new GoTo(Reference.place(phrases.place(c)));
            }
            return goTo(c);
        }
        if (t.is(PREP, "around") && c.peekAt(1) != null && NounPhrases.startsNounPhrase(c.peekAt(1))) {
            c.next();
            return explore(c); // "go round the castle", as "look around the castle"
        }
        if (NounPhrases.isRelation(t)) {
            return new GoTo(Reference.place(phrases.place(c))); // "go near the castle", "go behind the castle"
        }
        return goTo(c);
    }

    /** Go to the object the next noun phrase names. */
    private Goal goTo(Cursor c) {
        context.hint = context.answers.CAN_GO;
        context.question = context.answers.WHERE;
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.WHERE);
        }
        Phrase phrase = phrases.phrase(c, true);
        if (phrase == null) {
            throw Refusal.hint(context.hint);
        }
        if (phrase.world() || phrase.ground()) {
            throw Refusal.answer(context.answers.WHERE);
        }
        if (phrase.explicitCount() && phrase.count() > 1) {
            throw Refusal.answer(context.answers.ONE_PLACE);
        }
        Reference destination = phrase.ref();
        Place place = destination.place();
        if (destination.kind() == Kind.PLACE && place.anchor() == null && place.relation().sector() != null) {
            return new Head(place.relation().sector()); // "go to the north"
        }
        if (destination.kind() == Kind.PLACE && place.relation() == Relation.BEYOND && crossable(place.anchor())) {
            return new Cross(place.anchor());
        }
        context.antecedent = destination;
        return new GoTo(destination);
    }

    /** North, or north of the castle. */
    private Goal compassGoal(Lexeme direction, Cursor c) {
        if (c.peekIs(PREP, "of")) {
            return new GoTo(Reference.place(phrases.compass(direction, c)));
        }
        Double distance = distance(c);
        skipVagueAmount(c);
        return new Head(NounPhrases.sector(direction), distance);
    }

    /** "20 metres", "for 5 m": how far to walk, or null when the sentence does not say. */
    private Double distance(Cursor c) {
        int at = c.peekIs(PREP, "for") ? 1 : 0;
        Lexeme number = c.peekAt(at);
        Lexeme unit = c.peekAt(at + 1);
        if (number == null || !number.is(NUMBER) || unit == null || !unit.is(UNIT, "metre")) {
            return null;
        }
        for (int i = 0; i <= at + 1; i++) {
            c.next();
        }
        double distance = number.number();
        if (!(distance > 0 && distance <= RelativeMove.MAX_DISTANCE)) {
            throw Refusal.answer(context.answers.WALK_RANGE);
        }
        return distance;
    }

    /** A walk whose distance came before its direction: "walk 5 metres north", "go 3 m to the left". */
    private Goal walked(Goal goal, double distance) {
        if (goal instanceof Head head && head.distance() == null) {
            return new Head(head.direction(), distance);
        }
        if (goal instanceof RelativeMove move && move.distance() == null) {
            return new RelativeMove(move.direction(), distance);
        }
        throw Refusal.answer(context.answers.DISTANCE_WHICH_WAY);
    }

    /** "for a bit", "for a while", "a little": how far to walk is the agent's to choose. */
    private void skipVagueAmount(Cursor c) {
        while (true) {
            if (c.peekIs(PREP, "for") && c.peekAt(1) != null && c.peekAt(1).isAny(UNIT, "bit", "while", "moment")) {
                c.next();
                c.next();
            } else if (c.peek() != null && c.peek().isAny(UNIT, "bit", "while")) {
                c.next();
            } else {
                return;
            }
        }
    }

    /** After "back": "go back", "go back to the castle", "come back here". */
    private Goal back(Cursor c) {
        context.hint = context.answers.CAN_GO;
        if (c.atEnd()) {
            return new ComeBack();
        }
        if (c.peek().is(HERE) || c.peek().is(ME)) {
            c.next();
            return new ComeBack();
        }
        if (c.peekIs(PREP, "to")) {
            c.next();
            if (c.peek() != null && (c.peek().is(HERE) || c.peek().is(ME))) {
                c.next();
                return new ComeBack();
            }
        }
        if (c.peekIs(PREP, "back")) {
            c.next();
            return back(c);
        }
        return goTo(c);
    }

    /** "here", "there", "home", "me" after a verb of motion. */
    private Goal here(Lexeme word, boolean come) {
        if (word.is(HERE, "home") || come) {
            return new ComeBack();
        }
        if (word.is(HERE, "there")) {
            if (context.antecedent != null) {
                return new GoTo(context.antecedent); // "find a coconut and go there"
            }
            throw Refusal.answer(context.answers.WHERE_THERE);
        }
        throw Refusal.answer(context.answers.WHERE_HERE);
    }

    /** After "across", "over", "through": the landmark to cross, the river when none is said. */
    private Goal crossing(Cursor c) {
        context.hint = context.answers.CAN_CROSS;
        if (c.atEnd()) {
            return new Cross(Reference.to(Kind.RIVER));
        }
        if (c.peekIs(PREP, "to")) {
            c.next();
            return goTo(c); // "go over to the table"
        }
        Phrase phrase = phrases.phrase(c, true);
        if (phrase == null) {
            throw Refusal.hint(context.hint);
        }
        if (phrase.world() || phrase.ground()) {
            throw Refusal.hint(context.hint);
        }
        Goal goal = crossGoal(phrase.ref());
        if (c.peekIs(PREP, "to") && c.peekAt(1) != null && c.peekAt(1).is(PREP, "beyond")) {
            c.next(); // "walk over the bridge to the other side (of the river)"
            c.next();
            phrases.anchorOrRiver(c);
        }
        return goal;
    }

    /** After "beyond" (the other side of, behind, past): a crossing for the river, else a place. */
    private Goal beyond(Cursor c) {
        Reference anchor = phrases.anchorOrRiver(c);
        if (crossable(anchor)) {
            return new Cross(anchor);
        }
        return new GoTo(Reference.place(Place.of(Relation.BEYOND, anchor)));
    }

    private Goal cross(Cursor c) {
        context.hint = context.answers.CAN_CROSS;
        while (c.peekIs(PREP, "over") || c.peekIs(PREP, "across") || c.peekIs(PREP, "through")) {
            c.next();
        }
        if (c.atEnd()) {
            return new Cross(Reference.to(Kind.RIVER));
        }
        if (c.peekIs(PREP, "to")) {
            c.next();
        }
        if (c.peekIs(PREP, "beyond")) {
            c.next();
            return beyond(c);
        }
        return crossing(c);
    }

    private Goal crossGoal(Reference landmark) {
        Place place = landmark.place();
        if (landmark.kind() == Kind.RIVER && place != null && place.anchor() != null
                && place.anchor().kind() == Kind.BRIDGE) {
            return new Cross(place.anchor()); // "cross the river by the northern bridge"
        }
        if (crossable(landmark)) {
            return new Cross(landmark);
        }
        if (landmark.kind() == Kind.PLACE && place.relation() == Relation.BEYOND && crossable(place.anchor())) {
            return new Cross(place.anchor());
        }
        throw Refusal.answer(context.answers.crossNot(context.answers.noun(landmark, false)));
    }

    private boolean crossable(Reference reference) {
        return reference != null && (reference.kind() == Kind.RIVER || reference.kind() == Kind.BRIDGE
                || reference.kind() == Kind.FOREST);
    }

    /** After collect, pick, take, get, grab, eat, fetch, ... */
    private Goal collect(Cursor c, String lemma) {
        context.hint = context.answers.CAN_COLLECT;
        context.question = context.answers.WHAT_PICK;
        if (lemma.equals("take") && c.peekIs(DET, "a") && c.peekAt(1) != null && c.peekAt(1).isAny(SIDE, "left",
                "right")) {
            c.next();
            return sideways(c, false); // "take a left"
        }
        if (lemma.equals("get") && c.peek() != null && (c.peek().is(DIR) || c.peek().is(SIDE) || c.peek().is(HERE)
                || c.peek().isAny(PREP, "to", "back", "across", "over", "through", "beyond", "in", "near",
                "this-side", "away", "out", "on"))) {
            return go(c, false); // "get to the castle", "get back", "get across the river"
        }
        if (lemma.equals("get") && c.peek() != null && c.peek().is(VERB)) {
            return continuing(c); // "get exploring"
        }
        boolean only = false;
        while (c.peekIs(PREP, "up") || (c.peek() != null && (c.peek().is(ME) || c.peek().is(ONLY)))) {
            only |= c.next().is(ONLY); // "collect only bananas"
        }
        if (c.atEnd()) {
            if (lemma.equals("collect")) {
                return Collect.all(Reference.to(Kind.FRUIT)); // "collect", "go harvesting"
            }
            throw Refusal.answer(context.answers.WHAT_PICK);
        }
        Phrase phrase = phrases.phrase(c, false);
        if (phrase == null) {
            throw Refusal.hint(context.hint);
        }
        boolean back = false;
        while (c.peekIs(PREP, "up") || c.peekIs(PREP, "back") || (c.peek() != null && (c.peek().is(ME)
                || c.peek().is(ONLY)))
                || (c.peekIs(PREP, "to") && c.peekAt(1) != null && (c.peekAt(1).is(ME) || c.peekAt(1).is(HERE, "here")))) {
            Lexeme word = c.next(); // "pick the banana up", "bring it back", "bring them to me", "bananas only"
            only |= word.is(ONLY);
            if (word.is(PREP, "to")) {
                c.next();
                back = true;
            } else {
                back |= word.is(PREP, "back");
            }
        }
        if (phrase.world() || phrase.ground()) {
            throw Refusal.answer(context.answers.collectNotFruit(context.answers.world(phrase.ground())));
        }
        Reference what = phrase.ref();
        if (!what.isFruit()) {
            if (lemma.equals("take") && what.kind() == Kind.BRIDGE) {
                return crossGoal(what); // "take the bridge"
            }
            throw Refusal.answer(context.answers.collectNotFruit(context.answers.noun(what, false)));
        }
        if (phrase.pronoun() && what.equals(context.lastCollected)) {
            return back ? new ComeBack() : null; // "pick up a banana and bring it back", "... and eat it"
        }
        context.antecedent = what;
        context.lastCollected = what;
        Collect collect = new Collect(what, count(phrase));
        if (only) {
            if (!collect.isAll()) {
                throw Refusal.answer(context.answers.ONLY_WHAT);
            }
            return new Only(what);
        }
        return back ? Sequence.of(collect, new ComeBack()) : collect; // "if you find a banana, bring it to me"
    }

    private int count(Phrase phrase) {
        double count = phrase.count();
        if (count == Collect.ALL) {
            return Collect.ALL;
        }
        if (count < 1) {
            throw Refusal.answer(context.answers.ZERO);
        }
        if (count != Math.rint(count)) {
            throw Refusal.answer(context.answers.WHOLE);
        }
        if (count > MAX_COUNT) {
            throw Refusal.answer(context.answers.TOO_MANY);
        }
        return (int) count;
    }

    /** After turn, rotate, spin. */
    private Goal turn(Cursor c) {
        context.hint = context.answers.CAN_TURN;
        double degrees = Double.NaN;
        int sign = 0;
        boolean around = false;
        boolean bit = false;
        int times = 1;
        while (!c.atEnd()) {
            Lexeme t = c.peek();
            if (t.is(PREP, "to")) {
                Lexeme next = c.peekAt(1);
                if (next != null && next.is(VERB, "face")) {
                    c.next();
                    c.next();
                    return face(c); // "turn to face the castle"
                }
                if (next != null && (next.is(DIR) || next.is(SIDE))) {
                    c.next();
                    continue;
                }
                c.next();
                return lookAt(c); // "turn towards the castle"
            }
            if (t.is(PREP, "around") && c.peekAt(1) != null && c.peekAt(1).is(NUMBER)) {
                c.next(); // "turn about 90 degrees"
            } else if (t.is(PREP, "by") || t.is(UNIT, "degree")) {
                c.next();
            } else if (t.is(NUMBER)) {
                c.next();
                degrees = t.number();
            } else if (t.is(UNIT, "bit")) {
                c.next();
                bit = true;
            } else if (t.is(UNIT, "twice")) {
                c.next();
                times = 2;
            } else if (t.is(SIDE, "left")) {
                c.next();
                sign = 1;
            } else if (t.is(SIDE, "right")) {
                c.next();
                sign = -1;
            } else if (t.isAny(PREP, "around", "back", "behind-me") || t.is(SIDE, "backward")) {
                c.next();
                around = true;
            } else if (t.is(DIR) && Double.isNaN(degrees) && sign == 0 && !around) {
                c.next();
                return new Face(NounPhrases.sector(t)); // "turn north"
            } else {
                break;
            }
        }
        if (around) {
            return Turn.degrees((sign < 0 ? -180 : 180) * times);
        }
        if (!Double.isNaN(degrees)) {
            degrees *= times;
            if (!(degrees > 0 && degrees <= 360)) {
                throw Refusal.answer(context.answers.TURN_RANGE);
            }
            return Turn.degrees(sign < 0 ? -degrees : degrees);
        }
        if (sign != 0) {
            return Turn.degrees(sign * (bit ? 45 : 90) * times);
        }
        throw Refusal.answer(context.answers.WHICH_WAY);
    }

    /** "left", "right", "forward", "back": a turn when {@code walk} is false, else a step. */
    private Goal sideways(Cursor c, boolean walk) {
        Lexeme t = c.next();
        while (c.peek() != null && c.peek().is(SIDE)) {
            c.next(); // "straight ahead"
        }
        Double distance = walk ? distance(c) : null;
        skipVagueAmount(c);
        return switch (t.lemma()) {
            case "left" -> walk ? new RelativeMove(RelativeMove.Direction.LEFT, distance) : Turn.left();
            case "right" -> walk ? new RelativeMove(RelativeMove.Direction.RIGHT, distance) : Turn.right();
            case "backward" -> new RelativeMove(RelativeMove.Direction.BACKWARD, distance);
            default -> new RelativeMove(RelativeMove.Direction.FORWARD, distance);
        };
    }

    private Goal face(Cursor c) {
        context.hint = context.answers.CAN_TURN;
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.WHICH_FACE);
        }
        if (c.peekIs(PREP, "to")) {
            c.next();
        }
        Lexeme t = c.peek();
        if (t != null && t.is(DIR)) {
            c.next();
            return new Face(NounPhrases.sector(t));
        }
        if (t != null && (t.is(SIDE) || t.isAny(PREP, "around", "back", "behind-me"))) {
            return turn(c);
        }
        return lookAt(c);
    }

    private Goal lookAt(Cursor c) {
        context.question = context.answers.WHAT_LOOK_AT;
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.WHAT_LOOK_AT);
        }
        Phrase phrase = phrases.phrase(c, true);
        if (phrase == null || phrase.world() || phrase.ground()) {
            throw Refusal.hint(context.answers.CAN_LOOK);
        }
        context.antecedent = phrase.ref();
        return new LookAt(phrase.ref());
    }

    private Goal look(Cursor c) {
        context.hint = context.answers.CAN_LOOK;
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.WHAT_LOOK);
        }
        Lexeme t = c.peek();
        if (t.is(PREP, "for")) {
            return lookFor(c);
        }
        if (t.is(PREP, "at") || t.is(PREP, "to")) {
            c.next();
            return lookAt(c);
        }
        if (t.is(PREP, "around")) {
            c.next();
            return explore(c);
        }
        if (t.is(DIR)) {
            c.next();
            return new Face(NounPhrases.sector(t));
        }
        if (t.is(SIDE) || t.isAny(PREP, "back", "behind-me")) {
            return turn(c);
        }
        return lookAt(c);
    }

    /** After look for, find, search for, seek, hunt for. */
    private Goal lookFor(Cursor c) {
        context.hint = context.answers.CAN_LOOK;
        context.question = context.answers.WHAT_LOOK;
        while (c.peekIs(PREP, "for") || c.peekIs(PREP, "out") || (c.peek() != null && c.peek().is(ME))) {
            c.next();
        }
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.WHAT_LOOK);
        }
        Phrase phrase = phrases.phrase(c, true);
        if (phrase == null) {
            throw Refusal.hint(context.hint);
        }
        if (phrase.world() || phrase.ground()) {
            throw Refusal.answer(context.answers.WHAT_LOOK);
        }
        Reference what = phrase.ref();
        if (c.peekIs(PREP, "for")) {
            c.next(); // "search the forest for coconuts" reached through "find"
            Phrase target = phrases.phrase(c, true);
            if (target == null || target.ref() == null) {
                throw Refusal.hint(context.hint);
            }
            what = within(target.ref(), what);
        }
        context.antecedent = what;
        return new LookFor(what);
    }

    /** After search, scan: "search the forest", "search the forest for coconuts", "search for coconuts". */
    private Goal search(Cursor c) {
        context.hint = context.answers.CAN_EXPLORE;
        if (c.atEnd()) {
            return Explore.anywhere();
        }
        if (c.peekIs(PREP, "for")) {
            return lookFor(c);
        }
        return explore(c);
    }

    /** After explore, wander, roam, look around, search (an area). */
    private Goal explore(Cursor c) {
        context.hint = context.answers.CAN_EXPLORE;
        while (c.peekIs(PREP, "around") || c.peekIs(PREP, "through")) {
            c.next();
        }
        if (c.atEnd()) {
            return Explore.anywhere();
        }
        Lexeme t = c.peek();
        if (t.is(PREP, "for")) {
            return lookFor(c);
        }
        if (t.is(HERE) && !t.is(HERE, "home")) {
            c.next();
            return c.peekIs(PREP, "for") ? lookFor(c) : Explore.anywhere();
        }
        Reference area;
        if (t.is(PREP, "until")) {
            area = null;
        } else if (t.is(DIR)) {
            c.next();
            area = Reference.place(phrases.compass(t, c));
        } else if (NounPhrases.isRelation(t)) {
            area = Reference.place(phrases.place(c));
        } else {
            Phrase phrase = phrases.phrase(c, true);
            if (phrase == null) {
                throw Refusal.hint(context.hint);
            }
            area = phrase.world() || phrase.ground() ? null : phrase.ref();
        }
        if (c.peekIs(PREP, "for")) {
            c.next();
            Phrase target = phrases.phrase(c, true);
            if (target == null || target.ref() == null) {
                throw Refusal.hint(context.answers.CAN_LOOK);
            }
            Reference what = within(target.ref(), area);
            context.antecedent = what;
            return new LookFor(what);
        }
        if (c.peekIs(PREP, "until") && c.peekAt(1) != null && c.peekAt(1).isAny(VERB, "find", "approach", "look")) {
            c.next(); // "explore the forest until you find a coconut"
            c.next();
            Phrase target = phrases.phrase(c, true);
            if (target == null || target.ref() == null) {
                throw Refusal.hint(context.answers.CAN_LOOK);
            }
            Reference what = within(target.ref(), area);
            context.antecedent = what;
            return new LookFor(what);
        }
        if (area != null && area.isFruit()) {
            context.antecedent = area;
            return new LookFor(area); // "explore for bananas" said as "explore bananas"
        }
        return new Explore(area);
    }

    /** What to look for, restricted to an area unless it says its own place. */
    private Reference within(Reference what, Reference area) {
        if (area == null || what.place() != null) {
            return what;
        }
        if (area.kind() == Kind.PLACE) {
            return what.withPlace(area.place());
        }
        if (area.kind() == Kind.FOREST) {
            return what.withPlace(Place.of(Relation.IN, area));
        }
        return what.withPlace(Place.of(Relation.NEAR, area));
    }

    private Goal follow(Cursor c) {
        context.hint = context.answers.canFollow(lexicon.agentNames());
        context.question = context.answers.whom(lexicon.agentNames());
        if (c.peekIs(PREP, "after")) {
            c.next();
        }
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.whom(lexicon.agentNames()));
        }
        if (c.peek().is(ME)) {
            throw Refusal.answer(context.answers.followMe(lexicon.agentNames()));
        }
        Phrase phrase = phrases.phrase(c, true);
        if (phrase == null) {
            throw Refusal.hint(context.hint);
        }
        if (phrase.world() || phrase.ground()) {
            throw Refusal.answer(context.answers.whom(lexicon.agentNames()));
        }
        while (c.peekIs(PREP, "around") || (c.peek() != null && c.peek().is(NOUN, "world"))) {
            c.next(); // "follow Bunny around", "follow Bunny everywhere"
        }
        Reference agent = phrase.ref();
        if (agent.kind() != Kind.AGENT) {
            throw Refusal.answer(context.answers.followNotAgent(context.answers.noun(agent, true), lexicon.agentNames()));
        }
        context.antecedent = agent;
        return new Follow(agent);
    }

    private Goal stop(Cursor c) {
        context.hint = context.answers.CAN_STOP;
        Goal lift = rulesLifted(c);
        if (lift != null) {
            return lift; // "cancel the rules"
        }
        if (c.peek() != null && c.peek().is(VERB)) {
            c.next(); // "stop following Guppy", "stop moving": whatever it was doing
            while (!c.atEnd() && !c.peek().is(UNKNOWN)) {
                c.next();
            }
            return new Stop();
        }
        while (!c.atEnd() && (c.peek().is(HERE) || c.peek().is(PRON) || c.peek().is(DET)
                || c.peek().is(QUANT, "everything") || c.peek().is(QUANT, "all"))) {
            c.next(); // "stop here", "stop it", "stop that", "stop everything"
        }
        return new Stop();
    }

    private Goal waitHere(Cursor c) {
        context.hint = context.answers.CAN_WAIT;
        double seconds = Wait.UNTIL_TOLD;
        Goal before = null;
        while (!c.atEnd()) {
            Lexeme t = c.peek();
            if (t.is(HERE) && !t.is(HERE, "home")) {
                c.next();
            } else if (t.is(PREP, "for") && c.peekAt(1) != null && c.peekAt(1).is(ME)) {
                c.next();
                c.next(); // "wait for me"
            } else if (t.is(PREP, "for") && c.peekAt(1) != null && (c.peekAt(1).is(NUMBER) || c.peekAt(1).is(UNIT)
                    || c.peekAt(1).is(DET, "a"))) {
                c.next(); // "wait for ten seconds"
            } else if (t.is(NUMBER)) {
                c.next();
                double unit = 1;
                if (c.peek() != null && c.peek().is(UNIT)) {
                    unit = unitSeconds(c.next());
                }
                seconds = t.number() * unit;
            } else if (t.is(DET, "a") && c.peekAt(1) != null && c.peekAt(1).is(UNIT)) {
                c.next();
                seconds = unitSeconds(c.next());
            } else if (t.is(UNIT)) {
                seconds = unitSeconds(c.next());
            } else if (before == null && t.is(PREP, "this-side") && seconds == Wait.UNTIL_TOLD) {
                Reference anchor = phrases.place(c).anchor();
                return new Avoid(Reference.place(Place.of(Relation.BEYOND, anchor))); // "stay on this side of the river"
            } else if (before == null && NounPhrases.isRelation(t) && !t.is(PREP, "on-ground")) {
                before = new GoTo(Reference.place(phrases.place(c))); // "wait by the tree"
            } else {
                break;
            }
        }
        if (!(seconds >= 0) || (seconds > 86_400 && seconds != Wait.UNTIL_TOLD)) {
            throw Refusal.answer(context.answers.WAIT_RANGE);
        }
        Wait wait = new Wait(seconds);
        if (before != null) {
            GoTo goTo = (GoTo) before;
            Place place = goTo.destination().place();
            return Sequence.of(goTo, wait);
        }
        return wait;
    }

    private double unitSeconds(Lexeme unit) {
        return switch (unit.lemma()) {
            case "minute" -> 60;
            case "hour" -> 3600;
            case "moment" -> 5;
            case "bit" -> 10;
            case "while" -> 30;
            default -> 1;
        };
    }

    private Goal carryOn(Cursor c) {
        Lexeme t = c.peek();
        if (t != null && (t.is(DIR) || t.is(SIDE) || t.isAny(PREP, "to", "across", "over", "through", "beyond"))) {
            return go(c, false); // "proceed to the castle", "continue north"
        }
        while (c.peekIs(PREP, "with") || c.peekIs(PREP, "on")) {
            c.next();
        }
        if (c.atEnd()) {
            return new CarryOn();
        }
        return continuing(c);
    }

    /** After keep, start, continue: "keep going", "keep exploring", "start collecting". */
    private Goal keep(Cursor c) {
        return continuing(c);
    }

    private Goal continuing(Cursor c) {
        Lexeme t = c.peek();
        if (t == null) {
            return new CarryOn();
        }
        if (t.is(VERB, "go") && c.remaining() == 1) {
            c.next();
            return new CarryOn(); // "keep going"
        }
        if (t.is(VERB)) {
            return command(c);
        }
        throw Refusal.hint(context.answers.CAN_DO);
    }

    /** "do a u-turn", "do a 180". */
    private Goal doVerb(Cursor c) {
        while (c.peekIs(DET, "a")) {
            c.next();
        }
        if (c.peekIs(PREP, "around")) {
            c.next();
            return Turn.around();
        }
        if (c.peek() != null && c.peek().is(NUMBER)) {
            return turn(c);
        }
        throw Refusal.hint(context.answers.CAN_DO);
    }

    /** After leave, ignore, skip: "leave the coconuts (alone)"; "leave this side of the river" crosses it. */
    private Goal leave(Cursor c) {
        context.hint = context.answers.CAN_RULE;
        context.question = context.answers.LEAVE_WHAT;
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.LEAVE_WHAT);
        }
        if (c.peekIs(PREP, "this-side")) {
            Reference anchor = phrases.place(c).anchor();
            return new Cross(anchor); // "leave this side of the river", which "don't" makes a rule
        }
        Phrase phrase = phrases.phrase(c, false);
        if (phrase == null || phrase.ref() == null) {
            throw Refusal.hint(context.hint);
        }
        if (!phrase.ref().isFruit()) {
            throw Refusal.answer(context.answers.LEAVE_WHAT);
        }
        context.antecedent = phrase.ref();
        return new Leave(phrase.ref());
    }

    /**
     * After avoid, stay away from, keep off: "avoid the forest", "stay away from the river" (near it),
     * "avoid the coconuts" (leave them), "avoid going near the river".
     */
    private Goal avoid(Cursor c) {
        context.hint = context.answers.CAN_RULE;
        if (c.atEnd()) {
            throw Refusal.answer(context.answers.AVOID_WHAT);
        }
        if (c.peek().is(VERB)) {
            Rule rule = forbidding(command(c));
            if (rule == null) {
                throw Refusal.answer(context.answers.NEGATION);
            }
            return rule;
        }
        boolean near = false;
        if (c.peekIs(PREP, "near")) {
            c.next();
            near = true;
        }
        if (NounPhrases.isRelation(c.peek()) && !near) {
            return new Avoid(Reference.place(phrases.place(c))); // "avoid the other side of the river"
        }
        Phrase phrase = phrases.phrase(c, true);
        if (phrase == null || phrase.ref() == null) {
            throw Refusal.hint(context.hint);
        }
        Reference what = phrase.ref();
        if (what.isFruit()) {
            return new Leave(what);
        }
        if (what.kind() == Kind.START) {
            throw Refusal.answer(context.answers.AVOID_WHAT);
        }
        if (what.kind() == Kind.PLACE) {
            return new Avoid(what);
        }
        if (!near && (what.kind() == Kind.FOREST || what.kind() == Kind.BRIDGE)) {
            return new Avoid(what); // "avoid the forest": keep out of it
        }
        return new Avoid(Reference.place(Place.of(Relation.NEAR, what)));
    }

    /** "forget the rules"; "forget the coconuts" leaves them. */
    private Goal forget(Cursor c) {
        context.hint = context.answers.CAN_RULE;
        while (c.peekIs(PREP, "around") || c.peekIs(PREP, "about")) {
            c.next();
        }
        Goal lift = rulesLifted(c);
        if (lift != null) {
            return lift;
        }
        Phrase phrase = phrases.phrase(c, false);
        if (phrase != null && phrase.ref() != null && phrase.ref().isFruit()) {
            return new Leave(phrase.ref());
        }
        throw Refusal.hint(context.hint);
    }

    /** "lift the rules", "drop all the rules", "clear your restrictions". */
    private Goal liftRules(Cursor c) {
        context.hint = context.answers.CAN_RULE;
        Goal lift = rulesLifted(c);
        if (lift == null) {
            throw Refusal.hint(context.hint);
        }
        return lift;
    }

    /** "the rules", "all your rules", "every rule": every rule lifted; null (the cursor unmoved) otherwise. */
    private Goal rulesLifted(Cursor c) {
        int start = c.position();
        while (!c.atEnd() && (c.peek().is(DET) || c.peek().is(QUANT))) {
            c.next();
        }
        if (c.peek() != null && c.peek().is(RULE)) {
            c.next();
            return Lift.all();
        }
        c.seek(start);
        return null;
    }

    /** "use the bridge". */
    private Goal use(Cursor c) {
        context.hint = context.answers.CAN_CROSS;
        Phrase phrase = phrases.phrase(c, false);
        if (phrase == null || phrase.ref() == null || phrase.ref().kind() != Kind.BRIDGE) {
            throw Refusal.hint(context.hint);
        }
        return new Cross(phrase.ref());
    }

}
