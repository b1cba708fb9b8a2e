package io.orchard.agents.map;

import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * The rules a person set the agent that hold until lifted, as everything the agent does obeys
 * them: areas it must not walk into ("don't go near the river") and fruit it must not take
 * ("leave the coconuts", "only bananas from now on"). The errands put rules here as they are told
 * and take them out as they are lifted; the path planner plans around the areas, the coverage
 * offers no cell in them to explore, the harvester offers no fruit the rules forbid, and the
 * controller's motor neither walks into an area nor grasps such fruit, whatever behaviour asks it
 * to.
 *
 * <p>The areas and fruit tests are given as predicates over what the memory knows when they are
 * asked, so that "near the river" grows as the river is seen. Not thread-safe: it belongs to the
 * controller's thread, as the memory does.
 */
public final class Conduct {

    /** How finely the motor checks a straight walk for an area it must not enter, in units. */
    private static final double STEP = 0.2;

    private record PlaceRule(Object key, String words, Predicate<Point2> area) {
    }

    private record FruitRule(Object key, String words, Predicate<KnownFruit> forbids) {
    }

    private final List<PlaceRule> places = new ArrayList<>();
    private final List<FruitRule> fruit = new ArrayList<>();
    private long version;

    /**
     * Forbids walking into an area until {@link #lift lifted}.
     *
     * @param key   what lifts it: the rule as the errands keep it
     * @param words the rule in the agent's words, to say why it will not go somewhere: "you told me
     *              not to go near the river"
     * @param area  whether a point lies in the area, as far as the memory knows now
     */
    public void forbidPlaces(Object key, String words, Predicate<Point2> area) {
        places.add(new PlaceRule(Objects.requireNonNull(key, "key"), Objects.requireNonNull(words, "words"),
                Objects.requireNonNull(area, "area")));
        version++;
    }

    /**
     * Forbids taking fruit until {@link #lift lifted}.
     *
     * @param key     what lifts it
     * @param words   the rule in the agent's words: "you told me to leave the coconuts alone"
     * @param forbids whether the rule forbids a fruit
     */
    public void forbidFruit(Object key, String words, Predicate<KnownFruit> forbids) {
        fruit.add(new FruitRule(Objects.requireNonNull(key, "key"), Objects.requireNonNull(words, "words"),
                Objects.requireNonNull(forbids, "forbids")));
        version++;
    }

    /** Lifts the rules put here under {@code key}. */
    public void lift(Object key) {
        if (places.removeIf(rule -> rule.key().equals(key)) | fruit.removeIf(rule -> rule.key().equals(key))) {
            version++;
        }
    }

    /** Grows each time a rule is put or lifted. */
    public long version() {
        return version;
    }

    /** Whether a rule keeps the agent out of some area. */
    public boolean restrictsPlaces() {
        return !places.isEmpty();
    }

    /** Whether a rule keeps the agent from some fruit. */
    public boolean restrictsFruit() {
        return !fruit.isEmpty();
    }

    /** Whether a rule keeps the agent out of this point. */
    public boolean forbids(Point2 p) {
        for (PlaceRule rule : places) {
            if (rule.area().test(p)) {
                return true;
            }
        }
        return false;
    }

    /** The words of the first rule that keeps the agent out of this point; empty when none does. */
    public Optional<String> ruleAt(Point2 p) {
        for (PlaceRule rule : places) {
            if (rule.area().test(p)) {
                return Optional.of(rule.words());
            }
        }
        return Optional.empty();
    }

    /** What the first rule that keeps the agent out of this point was put here under; empty when none does. */
    public Optional<Object> ruleKeyAt(Point2 p) {
        for (PlaceRule rule : places) {
            if (rule.area().test(p)) {
                return Optional.of(rule.key());
            }
        }
        return Optional.empty();
    }

    /** What the first rule that forbids taking this fruit was put here under; empty when none does. */
    public Optional<Object> ruleKeyAgainst(KnownFruit candidate) {
        for (FruitRule rule : fruit) {
            if (rule.forbids().test(candidate)) {
                return Optional.of(rule.key());
            }
        }
        return Optional.empty();
    }

    /** Whether the rules let the agent take this fruit. */
    public boolean allows(KnownFruit candidate) {
        return ruleAgainst(candidate).isEmpty();
    }

    /** The words of the first rule that forbids taking this fruit; empty when none does. */
    public Optional<String> ruleAgainst(KnownFruit candidate) {
        for (FruitRule rule : fruit) {
            if (rule.forbids().test(candidate)) {
                return Optional.of(rule.words());
            }
        }
        return Optional.empty();
    }

    /**
     * How far along the straight walk from {@code from} to {@code to} the agent may go: {@code to}
     * when no rule's area lies on the way, else the last point before the first that one does.
     * Walking out of an area it stands in is allowed: the way is checked from where it leaves it.
     */
    public Point2 cut(Point2 from, Point2 to) {
        if (places.isEmpty()) {
            return to;
        }
        double length = from.distance(to);
        int steps = (int) Math.ceil(length / STEP);
        boolean outside = !forbids(from);
        Point2 last = from;
        for (int s = 1; s <= steps; s++) {
            double f = (double) s / steps;
            Point2 p = new Point2(from.x() + (to.x() - from.x()) * f, from.z() + (to.z() - from.z()) * f);
            boolean in = forbids(p);
            if (in && outside) {
                return last;
            }
            outside |= !in;
            last = p;
        }
        return to;
    }
}
