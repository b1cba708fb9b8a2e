package io.orchard.agents.errand;

import io.orchard.agents.language.Avoid;
import io.orchard.agents.language.Collect;
import io.orchard.agents.language.Cross;
import io.orchard.agents.language.Explore;
import io.orchard.agents.language.GoTo;
import io.orchard.agents.language.Goal;
import io.orchard.agents.language.Leave;
import io.orchard.agents.language.Lift;
import io.orchard.agents.language.Only;
import io.orchard.agents.language.Place;
import io.orchard.agents.language.Reference;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.agents.language.Rule;
import io.orchard.agents.language.WhenSee;
import io.orchard.agents.map.Conduct;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.RiverMap;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import java.util.function.Supplier;

/**
 * The rules a person set the agent, in force until lifted ({@link Rule}): it grounds each into the
 * memory's {@link Conduct}, which every behaviour of the agent obeys, says what it took on or
 * lifted, lists them when asked, refuses the errands that would break one, and keeps the conditions
 * ({@link WhenSee}) that the errands act on ({@link Watching}).
 *
 * <p>Areas and fruit are grounded the way goals are ({@link Grounder}), from where the agent stood
 * and faced when told, and again as the memory grows: "near the river" is wherever the river is
 * known to be, "this side of the river" the bank the agent stood on when told.
 */
final class Rulebook {

    /** How close to a landmark an agent told to avoid it may come: its size and this much more. */
    static final double CLEARANCE = 2;

    private final Kit kit;
    private final List<Rule> rules = new ArrayList<>();
    private final Watching watching;

    Rulebook(Kit kit) {
        this.kit = kit;
        this.watching = new Watching(kit);
    }

    /** The rules in force, oldest first. */
    List<Rule> rules() {
        return List.copyOf(rules);
    }

    /** The conditions in force, watched for. */
    Watching watching() {
        return watching;
    }

    /** Takes a rule on, in place of an {@link Only} for another: what the agent says. */
    String take(Rule rule) {
        if (rules.contains(rule)) {
            return kit.speech.keepToThatAlready(rule.statement(kit.language));
        }
        String replaced = "";
        if (rule instanceof Only) {
            for (Rule old : List.copyOf(rules)) {
                if (old instanceof Only) {
                    drop(old);
                    replaced = kit.speech.takesThePlaceOf(old.reason(kit.language));
                }
            }
        }
        rules.add(rule);
        Conduct conduct = kit.memory.conduct();
        Grounder grounder = new Grounder(kit.memory);
        grounder.told(kit.here(), kit.motor.heading());
        if (rule instanceof Avoid avoid) {
            conduct.forbidPlaces(rule, rule.reason(), area(grounder, avoid.area()));
        } else if (rule instanceof Leave leave) {
            Predicate<KnownFruit> fits = fits(grounder, leave.what());
            conduct.forbidFruit(rule, rule.reason(), fits);
        } else if (rule instanceof Only only) {
            Predicate<KnownFruit> fits = fits(grounder, only.what());
            conduct.forbidFruit(rule, rule.reason(), fits.negate());
        } else if (rule instanceof WhenSee when) {
            watching.watch(when, grounder);
        }
        String inside = rule instanceof Avoid && conduct.forbids(kit.here())
                ? kit.speech.leaveFirst() : "";
        return rule.restatement(kit.language) + replaced + inside;
    }

    /** Lifts the rules the words are about, or every rule: what the agent says. */
    String lift(Lift lift) {
        List<Rule> lifted = matching(lift.what());
        if (lifted.isEmpty()) {
            return lift.what() == null ? kit.speech.noRulesToForget() : kit.speech.noRuleAgainstThat();
        }
        lifted.forEach(this::drop);
        String said = lift.restatement(kit.language);
        List<String> others = new ArrayList<>();
        if (lift.what() != null) {
            for (Rule rule : lifted) {
                if (!saysTheSame(rule, lift.what())) {
                    others.add(rule.reason(kit.language));
                }
            }
        }
        if (others.isEmpty()) {
            return said;
        }
        return said.substring(0, said.length() - 1) + kit.speech.thatLifts(others);
    }

    /** The rules in force, as the agent states them for "what are your rules?". */
    String statements() {
        if (rules.isEmpty()) {
            return kit.speech.noRules();
        }
        List<String> said = new ArrayList<>();
        for (Rule rule : rules) {
            said.add(rule.statement(kit.language));
        }
        return kit.speech.rules(said);
    }

    /** Why the rules forbid this step outright, as the agent says it; null when they do not. */
    @Nullable String refusal(Goal step) {
        for (Rule rule : rules) {
            if (forbids(rule, step)) {
                return kit.speech.wontBreak(rule.reason(kit.language));
            }
        }
        return null;
    }

    private void drop(Rule rule) {
        rules.remove(rule);
        kit.memory.conduct().lift(rule);
        if (rule instanceof WhenSee when) {
            watching.forget(when);
        }
    }

    /** The rules a lift of these words lifts: exactly those about them, else those about the same landmark or fruit. */
    private List<Rule> matching(@Nullable Reference what) {
        if (what == null) {
            return List.copyOf(rules);
        }
        List<Rule> exact = new ArrayList<>();
        List<Rule> related = new ArrayList<>();
        for (Rule rule : rules) {
            if (saysTheSame(rule, what)) {
                exact.add(rule);
            } else if (what.isFruit() && rule instanceof Leave leave && overlap(leave.what().kind(), what.kind())) {
                related.add(rule);
            } else if (what.isFruit() && rule instanceof Only only && !covers(only.what().kind(), what.kind())) {
                related.add(rule); // "you may take coconuts again" ends "only bananas"
            } else if (!what.isFruit() && rule instanceof Avoid avoid && subject(avoid.area()) == subject(what)) {
                related.add(rule);
            }
        }
        if (what.isFruit()) {
            exact.addAll(related); // every rule that keeps it from that fruit
            return exact;
        }
        return exact.isEmpty() ? related : exact;
    }

    private static boolean saysTheSame(Rule rule, Reference what) {
        return (rule instanceof Avoid avoid && avoid.area().equals(what))
                || (rule instanceof Leave leave && leave.what().equals(what));
    }

    private static boolean overlap(Kind a, Kind b) {
        return a == Kind.FRUIT || b == Kind.FRUIT || a == b;
    }

    /** Whether fruit of kind {@code wanted} is all of kind {@code allowed}. */
    private static boolean covers(Kind allowed, Kind wanted) {
        return allowed == Kind.FRUIT || allowed == wanted;
    }

    /** What an area is about: its anchor's kind for a place ("near the river": the river), else its own. */
    private static Kind subject(Reference area) {
        return area.kind() == Kind.PLACE && area.place().anchor() != null ? area.place().anchor().kind() : area.kind();
    }

    /** Whether the rule forbids the step whatever the agent knows: the very fruit or area it names. */
    private static boolean forbids(Rule rule, Goal step) {
        if (step instanceof Collect collect) {
            Reference what = collect.what();
            if (rule instanceof Leave leave) {
                Reference left = leave.what();
                return left.place() == null && left.id() == null && covers(left.kind(), what.kind());
            }
            if (rule instanceof Only only) {
                Reference kept = only.what();
                return kept.place() == null && what.kind() != Kind.FRUIT && !covers(kept.kind(), what.kind());
            }
            return false;
        }
        if (!(rule instanceof Avoid avoid)) {
            return false;
        }
        Reference area = avoid.area();
        if (step instanceof GoTo goTo) {
            return within(goTo.destination(), area);
        }
        if (step instanceof Explore explore) {
            return explore.area() != null && within(explore.area(), area);
        }
        if (step instanceof Cross cross) {
            Kind landmark = cross.landmark().kind();
            boolean otherBank = area.kind() == Kind.PLACE && area.place().relation() == Place.Relation.BEYOND
                    && area.place().anchor() != null && area.place().anchor().kind() == Kind.RIVER;
            return (otherBank && (landmark == Kind.RIVER || landmark == Kind.BRIDGE)) || cross.landmark().equals(area);
        }
        return false;
    }

    /**
     * Whether the words name the area or a part of it. There is one castle, one river and one forest,
     * so a rule about the whole of one ("keep out of the forest") covers it wherever the words place
     * it ("the woods on the other side of the river").
     */
    private static boolean within(Reference target, Reference area) {
        if (target.equals(area)) {
            return true;
        }
        boolean landmark = area.kind() == Kind.FOREST || area.kind() == Kind.RIVER || area.kind() == Kind.CASTLE;
        return landmark && area.equals(Reference.to(area.kind())) && target.kind() == area.kind();
    }

    // ---- grounding ------------------------------------------------------------------------------

    /** Whether a point lies in the area, as the memory knows it when asked. */
    private Predicate<Point2> area(Grounder grounder, Reference area) {
        if (area.kind() == Kind.PLACE) {
            Place place = area.place();
            Reference anchor = place.anchor();
            if (anchor != null && (anchor.kind() == Kind.RIVER || anchor.kind() == Kind.BRIDGE)
                    && (place.relation() == Place.Relation.BEYOND || place.relation() == Place.Relation.THIS_SIDE_OF)) {
                return bank(place.relation() == Place.Relation.BEYOND);
            }
            Supplier<Predicate<Known>> at = fresh(() -> grounder.where(place));
            return p -> at.get().test(Known.standing(p));
        }
        if (area.kind() == Kind.FOREST) {
            Supplier<Predicate<Known>> at = fresh(() -> grounder.where(Place.of(Place.Relation.IN, area)));
            return p -> at.get().test(Known.standing(p));
        }
        Supplier<List<Known>> things = fresh(() -> grounder.select(area, grounder.fitting(area)));
        return p -> {
            for (Known thing : things.get()) {
                if (thing.bridge() != null ? thing.bridge().covers(p, -CLEARANCE, CLEARANCE)
                        : thing.where().distance(p) <= thing.size() + CLEARANCE) {
                    return true;
                }
            }
            return false;
        };
    }

    /**
     * The other bank ({@code beyond}, with the water between, a bridge's deck included) or this one,
     * from the bank the agent stood on when told, or, when it did not know the river yet, the first
     * bank it knows it stands on.
     */
    private Predicate<Point2> bank(boolean beyond) {
        RiverMap river = kit.memory.river();
        RiverMap.Side[] mine = {standing(kit.here())};
        return p -> {
            if (mine[0] == null) {
                mine[0] = standing(kit.memory.position());
                if (mine[0] == null) {
                    return false;
                }
            }
            RiverMap.Side theirs = river.side(p.x(), p.z(), 0);
            if (theirs == RiverMap.Side.WATER) {
                // A bridge's deck is over the water: on it, the agent is no longer on its bank, and the
                // far bank may lie beyond the river as the memory knows it so far.
                return beyond;
            }
            return (theirs == RiverMap.Side.LOW || theirs == RiverMap.Side.HIGH) && (theirs != mine[0]) == beyond;
        };
    }

    private RiverMap.Side standing(Point2 p) {
        RiverMap.Side side = kit.memory.river().side(p.x(), p.z(), 0);
        return side == RiverMap.Side.LOW || side == RiverMap.Side.HIGH ? side : null;
    }

    /** Whether a fruit fits the words, kind, id and place, whatever their distance or size. */
    private Predicate<KnownFruit> fits(Grounder grounder, Reference what) {
        Supplier<Predicate<Known>> at = what.place() == null ? null : fresh(() -> grounder.where(what.place()));
        return fruit -> what.kind().matches(fruit.kind()) && (what.id() == null || what.id().equals(fruit.id()))
                && (at == null || at.get().test(Known.fruit(fruit)));
    }

    /** A value made again whenever what the memory knows has changed. */
    private <T> Supplier<T> fresh(Supplier<T> make) {
        return new Supplier<>() {
            private long terrain = -1;
            private long fruit = -1;
            private T value;

            @Override
            public T get() {
                long t = kit.memory.terrainVersion();
                long f = kit.memory.fruitVersion();
                if (value == null || t != terrain || f != fruit) {
                    value = make.get();
                    terrain = t;
                    fruit = f;
                }
                return value;
            }
        };
    }
}
