package io.orchard.agents.language;

import io.orchard.agents.language.Reference.Kind;
import io.orchard.agents.language.Reference.Size;
import java.util.List;
import java.util.Map;

/**
 * The agent's English restatement of a goal: "Going to pick up the nearest banana that lies on a
 * table.", "Going to the castle, then picking up a tomato." Objects are "the" when they are
 * unique (the castle, the river, the forest) or picked by a superlative, and "a" otherwise, since
 * any object that fits will do.
 */
final class Restatement {

    private static final String[] NUMBERS = {"zero", "one", "two", "three", "four", "five", "six", "seven", "eight",
        "nine", "ten", "eleven", "twelve"};

    private Restatement() {
    }

    static String of(Goal goal) {
        String text;
        if (goal instanceof Rule || goal instanceof Lift) {
            text = rule(goal);
        } else if (goal instanceof Sequence sequence) {
            StringBuilder steps = new StringBuilder();
            Goal previous = null;
            for (Goal step : sequence.steps()) {
                boolean rule = step instanceof Rule || step instanceof Lift;
                boolean afterRule = previous instanceof Rule || previous instanceof Lift;
                if (previous == null) {
                    steps.append(rule ? rule(step) : lead(step));
                } else if (rule || afterRule) {
                    steps.append("; ").append(rule ? rule(step) : lead(step)); // a rule holds, not a step in turn
                } else {
                    steps.append(", then ").append(gerund(step));
                }
                previous = step;
            }
            text = steps.toString();
        } else {
            text = lead(goal);
        }
        return Character.toUpperCase(text.charAt(0)) + text.substring(1) + ".";
    }

    /** A rule as the agent takes it on: "from now on I won't go near the river". */
    static String rule(Goal goal) {
        if (goal instanceof Avoid avoid) {
            return "from now on I" + avoided(avoid.area());
        }
        if (goal instanceof Leave leave) {
            return "from now on I'll leave " + every(leave.what()) + " alone";
        }
        if (goal instanceof Only only) {
            return "from now on I'll collect only " + phrase(only.what(), Collect.ALL, true);
        }
        if (goal instanceof WhenSee when) {
            return "from now on, whenever I see " + noun(when.what()) + ", I'll " + infinitive(when.then(), when.what());
        }
        if (goal instanceof Lift lift) {
            if (lift.what() == null) {
                return "all right: I've forgotten all my rules";
            }
            return "all right: I may " + (lift.what().isFruit() ? "take " + phrase(lift.what(), Collect.ALL, true)
                    : "go " + where(lift.what())) + " again";
        }
        return lead(goal);
    }

    /** A rule as it holds: "I don't go near the river", "whenever I see a banana, I pick it up". */
    static String statement(Rule rule) {
        String text = rule(rule);
        text = text.startsWith("from now on, ") ? text.substring("from now on, ".length())
                : text.startsWith("from now on ") ? text.substring("from now on ".length()) : text;
        return text.replace("I won't ", "I don't ").replace("I'll ", "I ").replace("I I ", "I ");
    }

    /** A rule as a reason: "your rule not to go near the river", "your rule to leave the coconuts alone". */
    static String reason(Rule rule) {
        if (rule instanceof Avoid avoid) {
            String avoided = avoided(avoid.area());
            return avoided.startsWith("'ll ") ? "your rule to " + avoided.substring(4)
                    : "your rule not to " + avoided.substring(" won't ".length());
        }
        if (rule instanceof Leave leave) {
            return "your rule to leave " + every(leave.what()) + " alone";
        }
        if (rule instanceof Only only) {
            return "your rule to collect only " + phrase(only.what(), Collect.ALL, true);
        }
        return "your rule that " + statement(rule);
    }

    /** What a rule to avoid an area keeps the agent from: "won't go near the river", "'ll stay on this side of the river". */
    private static String avoided(Reference area) {
        Place place = area.place();
        if (area.kind() == Kind.PLACE && place.relation() == Place.Relation.BEYOND && place.anchor() != null
                && (place.anchor().kind() == Kind.RIVER || place.anchor().kind() == Kind.BRIDGE)) {
            return "'ll stay on this side of " + noun(place.anchor());
        }
        return " won't go " + where(area);
    }

    /** Where "go" leads, for an area: "near the river", "into the forest", "to the castle", "north of the castle". */
    static String where(Reference area) {
        if (area.kind() == Kind.FOREST) {
            return "into " + noun(area);
        }
        if (area.kind() != Kind.PLACE) {
            return "to " + noun(area);
        }
        String destination = destination(area);
        return destination.startsWith("to the area ") ? destination.substring("to the area ".length()) : destination;
    }

    /** Fruit as a rule names all of it: "the coconuts", "the tomatoes on the tables". */
    private static String every(Reference what) {
        return (what.kind() == Kind.FRUIT && what.place() == null ? "" : "the ") + phrase(what, Collect.ALL, true);
    }

    /**
     * What a condition does, as "I'll ..." goes on: "pick it up", "go there", "follow him", "pick it up, then come
     * back". The thing seen is "it" (or "him", "there").
     */
    private static String infinitive(Goal then, Reference seen) {
        List<Goal> steps = then instanceof Sequence sequence ? sequence.steps() : List.of(then);
        StringBuilder text = new StringBuilder();
        for (Goal step : steps) {
            if (text.length() > 0) {
                text.append(", then ");
            }
            String gerund = gerund(step);
            String noun = noun(seen);
            String pronoun = seen.kind() == Kind.AGENT ? "him" : "it";
            gerund = gerund.replace("going to " + noun, "going there").replace("picking up " + noun,
                    "picking " + pronoun + " up");
            if (!(seen.kind() == Kind.AGENT && seen.name() != null)) {
                gerund = gerund.replace(noun, pronoun);
            } else {
                gerund = gerund.replace(" " + noun, " " + pronoun);
            }
            int space = gerund.indexOf(' ');
            String verb = space < 0 ? gerund : gerund.substring(0, space);
            text.append(INFINITIVES.getOrDefault(verb, verb)).append(space < 0 ? "" : gerund.substring(space));
        }
        return text.toString();
    }

    private static final Map<String, String> INFINITIVES = Map.ofEntries(Map.entry("going", "go"),
            Map.entry("picking", "pick"), Map.entry("crossing", "cross"), Map.entry("heading", "head"),
            Map.entry("stepping", "step"), Map.entry("coming", "come"), Map.entry("turning", "turn"),
            Map.entry("looking", "look"), Map.entry("exploring", "explore"), Map.entry("following", "follow"),
            Map.entry("stopping", "stop"), Map.entry("waiting", "wait"));

    /** The first step as the agent announces it: "going to pick up a tomato". */
    private static String lead(Goal goal) {
        if (goal instanceof Collect collect) {
            return "going to pick up " + collected(collect);
        }
        if (goal instanceof Cross cross) {
            return "going to cross " + noun(cross.landmark());
        }
        return gerund(goal);
    }

    /** A step after the first: "picking up a tomato". */
    private static String gerund(Goal goal) {
        if (goal instanceof GoTo goTo) {
            return "going " + destination(goTo.destination());
        }
        if (goal instanceof Cross cross) {
            return "crossing " + noun(cross.landmark());
        }
        if (goal instanceof Head head) {
            return head.distance() == null ? "heading " + head.direction().wireName()
                    : "going " + RelativeMove.metres(head.distance()) + " " + head.direction().wireName();
        }
        if (goal instanceof RelativeMove move) {
            if (move.distance() != null) {
                String how = RelativeMove.metres(move.distance());
                return switch (move.direction()) {
                    case FORWARD -> "going " + how + " forward";
                    case BACKWARD -> "stepping " + how + " back";
                    case LEFT -> "going " + how + " to my left";
                    case RIGHT -> "going " + how + " to my right";
                };
            }
            return switch (move.direction()) {
                case FORWARD -> "going forward";
                case BACKWARD -> "stepping back";
                case LEFT -> "going to my left";
                case RIGHT -> "going to my right";
            };
        }
        if (goal instanceof ComeBack) {
            return "coming back";
        }
        if (goal instanceof Collect collect) {
            return "picking up " + collected(collect);
        }
        if (goal instanceof Turn turn) {
            return turning(turn.degrees());
        }
        if (goal instanceof Face face) {
            return "turning to face " + face.direction().wireName();
        }
        if (goal instanceof LookAt lookAt) {
            return "turning to face " + noun(lookAt.target());
        }
        if (goal instanceof LookFor lookFor) {
            return "looking for " + searched(lookFor.what());
        }
        if (goal instanceof Explore explore) {
            return explore.area() == null ? "exploring" : "exploring " + area(explore.area());
        }
        if (goal instanceof Follow follow) {
            return "following " + noun(follow.agent());
        }
        if (goal instanceof Stop) {
            return "stopping";
        }
        if (goal instanceof Wait wait) {
            return wait.isUntilTold() ? "waiting here" : "waiting here for " + duration(wait.seconds());
        }
        if (goal instanceof CarryOn) {
            return "carrying on by myself";
        }
        if (goal instanceof Ask ask) {
            return asked(ask);
        }
        throw new IllegalArgumentException("no restatement for " + goal);
    }

    /** A question as the agent restates it: "you asked what I see". */
    private static String asked(Ask ask) {
        return "you asked " + switch (ask.topic()) {
            case SEE -> ask.about() == null ? "what I see" : "whether I see " + searched(ask.about());
            case WHERE -> "where I am";
            case COLLECTED -> "what " + (ask.about() == null ? "fruit" : searched(ask.about())) + " I have collected";
            case DOING -> "what I am doing";
            case WHY -> "why I stopped";
            case WHERE_IS -> "where " + searched(ask.about()) + (plural(ask.about()) ? " are" : " is");
            case CAN -> "what I can do";
            case HEADING -> "which way I face";
            case RULES -> "what my rules are";
        };
    }

    private static boolean plural(Reference reference) {
        return reference.isFruit() && reference.distance() == null && reference.size() != Size.LARGEST
                && reference.size() != Size.SMALLEST;
    }

    /** Every object of a reference, without an article: "coconuts that lie on a table". */
    static String many(Reference reference) {
        return phrase(reference, Collect.ALL, true);
    }

    /** One object of a reference, with its article: "a tree", "the castle", "the nearest banana on a table". */
    static String noun(Reference reference) {
        return phrase(reference, 1, false);
    }

    private static String collected(Collect collect) {
        return phrase(collect.what(), collect.count(), false);
    }

    /** What is looked for: fruit in the plural unless one is picked out ("coconuts", "the nearest coconut"). */
    private static String searched(Reference what) {
        boolean one = what.distance() != null || what.size() == Size.LARGEST || what.size() == Size.SMALLEST;
        return phrase(what, what.isFruit() && !one ? Collect.ALL : 1, true);
    }

    private static String phrase(Reference reference, int count, boolean bare) {
        if (reference.kind() == Kind.PLACE) {
            return area(reference);
        }
        if (reference.kind() == Kind.START) {
            return "where I started";
        }
        boolean plural = count > 1;
        StringBuilder core = new StringBuilder();
        boolean fromSide = reference.distance() == Reference.Distance.LEFTMOST
                || reference.distance() == Reference.Distance.RIGHTMOST;
        if (reference.ordinal() != null) {
            core.append(ordinal(reference.ordinal())).append(' ');
        }
        if (reference.distance() != null && !(fromSide && reference.ordinal() != null)) {
            core.append(reference.distance().wireName()).append(' ');
        }
        if (reference.size() != null) {
            core.append(reference.size().wireName()).append(' ');
        }
        if (reference.name() != null) {
            core.append(reference.name());
        } else {
            core.append(plural ? plural(reference.kind()) : reference.kind().wireName());
        }
        if (reference.id() != null) {
            core.append(' ').append(reference.id());
        }
        if (fromSide && reference.ordinal() != null) {
            core.append(reference.distance() == Reference.Distance.LEFTMOST ? " from the left" : " from the right");
        }
        if (reference.place() != null) {
            core.append(' ').append(relation(reference.place(), reference.isFruit(), plural));
        }
        String text = core.toString();
        if (reference.name() != null && reference.distance() == null && reference.size() == null) {
            return text;
        }
        if (count == Collect.ALL) {
            return bare ? text : "all the " + text;
        }
        boolean definite = reference.distance() != null || reference.id() != null || picked(reference.place()) || reference.size() == Size.LARGEST
                || reference.size() == Size.SMALLEST || reference.kind() == Kind.CASTLE
                || reference.kind() == Kind.RIVER || reference.kind() == Kind.FOREST;
        if (plural) {
            String number = count < NUMBERS.length ? NUMBERS[count] : Integer.toString(count);
            return (definite ? "the " : "") + number + " " + text;
        }
        if (definite) {
            return "the " + text;
        }
        return ("aeiou".indexOf(text.charAt(0)) >= 0 ? "an " : "a ") + text;
    }

    /** A place near an anchor or from the agent's heading: "near the river", "near me", "on my left". */
    private static String mine(Place place) {
        return switch (place.relation()) {
            case LEFT -> "on my left";
            case RIGHT -> "on my right";
            case AHEAD -> "in front of me";
            case BEHIND -> "behind me";
            default -> place.anchor() == null ? "near me" : "near " + noun(place.anchor());
        };
    }

    /** Whether a place picks out one object: "closest to the bridge". */
    private static boolean picked(Place place) {
        return place != null && (place.relation() == Place.Relation.CLOSEST_TO
                || place.relation() == Place.Relation.FARTHEST_FROM);
    }

    private static String plural(Kind kind) {
        return switch (kind) {
            case FRUIT -> "fruit";
            case TOMATO -> "tomatoes";
            case FOREST -> "forests";
            default -> kind.wireName() + "s";
        };
    }

    /** Where a referred object is: "that lies on a table", "near the river", "north of the castle". */
    private static String relation(Place place, boolean fruit, boolean plural) {
        String lies = fruit ? (plural ? "that lie " : "that lies ") : "";
        String hangs = fruit ? (plural ? "that hang " : "that hangs ") : "";
        Reference anchor = place.anchor();
        return switch (place.relation()) {
            case ON -> lies + "on " + noun(anchor);
            case IN -> (anchor.kind() == Kind.TREE ? hangs : "") + "in " + noun(anchor);
            case UNDER -> lies + "under " + noun(anchor);
            case ON_GROUND -> lies + "on the ground";
            case NEAR, LEFT, RIGHT, AHEAD, BEHIND -> mine(place);
            case CLOSEST_TO -> "closest to " + noun(anchor);
            case FARTHEST_FROM -> "farthest from " + noun(anchor);
            case BEYOND -> "on the other side of " + noun(anchor);
            case THIS_SIDE_OF -> "on this side of " + noun(anchor);
            default -> anchor == null ? "to the " + place.relation().sector().wireName()
                    : place.relation().sector().wireName() + " of " + noun(anchor);
        };
    }

    /** Where to go: "to a tree", "near the castle", "to the other side of the castle". */
    private static String destination(Reference reference) {
        if (reference.kind() != Kind.PLACE) {
            return "to " + noun(reference);
        }
        Place place = reference.place();
        Reference anchor = place.anchor();
        return switch (place.relation()) {
            case ON -> "onto " + noun(anchor);
            case IN -> "into " + noun(anchor);
            case UNDER -> "under " + noun(anchor);
            case ON_GROUND -> "down to the ground";
            case NEAR -> mine(place);
            case LEFT, RIGHT, AHEAD, BEHIND -> "to the area " + mine(place);
            case CLOSEST_TO -> "to the place closest to " + noun(anchor);
            case FARTHEST_FROM -> "to the place farthest from " + noun(anchor);
            case BEYOND -> "to the other side of " + noun(anchor);
            case THIS_SIDE_OF -> "to this side of " + noun(anchor);
            default -> anchor == null ? place.relation().sector().wireName()
                    : place.relation().sector().wireName() + " of " + noun(anchor);
        };
    }

    /** An area to explore: "the forest", "the other side of the river", "the area near the castle". */
    private static String area(Reference reference) {
        if (reference.kind() == Kind.FOREST) {
            return noun(reference);
        }
        if (reference.kind() != Kind.PLACE) {
            return "the area near " + noun(reference);
        }
        Place place = reference.place();
        Reference anchor = place.anchor();
        return switch (place.relation()) {
            case IN -> noun(anchor);
            case ON_GROUND -> "the ground";
            case BEYOND -> "the other side of " + noun(anchor);
            case THIS_SIDE_OF -> "this side of " + noun(anchor);
            case ON -> "the area on " + noun(anchor);
            case UNDER -> "the area under " + noun(anchor);
            case NEAR, LEFT, RIGHT, AHEAD, BEHIND -> "the area " + mine(place);
            case CLOSEST_TO -> "the area closest to " + noun(anchor);
            case FARTHEST_FROM -> "the area farthest from " + noun(anchor);
            default -> anchor == null ? "the " + place.relation().sector().wireName()
                    : "the area " + place.relation().sector().wireName() + " of " + noun(anchor);
        };
    }

    private static final String[] ORDINALS = {"zeroth", "first", "second", "third", "fourth", "fifth", "sixth",
        "seventh", "eighth", "ninth", "tenth", "eleventh", "twelfth", "thirteenth", "fourteenth", "fifteenth",
        "sixteenth", "seventeenth", "eighteenth", "nineteenth", "twentieth"};

    /** "second", "third", ... */
    static String ordinal(int n) {
        return n < ORDINALS.length ? ORDINALS[n] : Notation.ordinal(n);
    }

    private static String turning(double degrees) {
        long rounded = Math.round(degrees);
        if (rounded == 90) {
            return "turning left";
        }
        if (rounded == -90) {
            return "turning right";
        }
        if (Math.abs(rounded) == 180) {
            return "turning around";
        }
        return "turning " + Notation.number(Math.abs(degrees)) + " degrees to the " + (degrees > 0 ? "left" : "right");
    }

    private static String duration(double seconds) {
        if (seconds >= 60 && seconds % 60 == 0) {
            long minutes = (long) (seconds / 60);
            return minutes + (minutes == 1 ? " minute" : " minutes");
        }
        return Notation.number(seconds) + (seconds == 1 ? " second" : " seconds");
    }
}
