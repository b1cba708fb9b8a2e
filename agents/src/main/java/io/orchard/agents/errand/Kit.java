package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Explorer;
import io.orchard.agents.behaviour.Harvester;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.Navigator;
import io.orchard.agents.behaviour.PathPlanner;
import io.orchard.agents.language.Discourse;
import io.orchard.agents.language.Language;
import io.orchard.agents.language.Reference;
import io.orchard.agents.language.Rule;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Point2;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/** The behaviours the pursuits of instructed goals share, made once for an agent. */
final class Kit {

    final WorldMemory memory;
    final Motor motor;
    final PathPlanner planner;
    final Navigator navigator;
    final Harvester harvester;
    final Explorer explorer;
    final Grounder grounder;
    /** The language the agent answers in: that of the last sentence it was told. */
    Language language = Language.ENGLISH;
    /** What the agent says, in that language. */
    final Speech speech = new Speech(this);
    /** What the agent spoke about or looked at, most recent first. */
    private final List<Discourse.Mention> mentioned = new ArrayList<>();
    private static final int MENTIONS = 8;

    Kit(WorldMemory memory, Motor motor, PathPlanner planner) {
        this.memory = memory;
        this.motor = motor;
        this.planner = planner;
        this.navigator = new Navigator(memory, motor, planner);
        this.harvester = new Harvester(memory, motor, navigator);
        this.explorer = new Explorer(memory, planner);
        this.grounder = new Grounder(memory);
    }

    /** The agent spoke about, turned to or chose this thing: "that table" may mean it now. */
    void mention(Known thing) {
        if (!thing.kind().hasIds() && thing.kind() != Reference.Kind.AGENT) {
            return;
        }
        Discourse.Mention mention = new Discourse.Mention(thing.kind(), thing.id());
        mentioned.remove(mention);
        mentioned.add(0, mention);
        if (mentioned.size() > MENTIONS) {
            mentioned.remove(mentioned.size() - 1);
        }
    }

    /** What the agent spoke about or looked at last. */
    Discourse discourse() {
        return new Discourse(mentioned);
    }

    /**
     * The rule that keeps the agent out of this point, as a reason in the language spoken ("your rule not
     * to go near the river"); empty when none.
     */
    Optional<String> forbidden(Point2 p) {
        return memory.conduct().ruleKeyAt(p).map(this::reason);
    }

    /** The rule that forbids taking this fruit, as a reason in the language spoken; empty when none. */
    Optional<String> rule(KnownFruit fruit) {
        return memory.conduct().ruleKeyAgainst(fruit).map(this::reason);
    }

    private String reason(Object rule) {
        return rule instanceof Rule told ? told.reason(language) : String.valueOf(rule);
    }

    /** The nearest place the agent may stand that no rule keeps it out of, looking up to 60 units away; empty when none. */
    Optional<Point2> nearestAllowed() {
        Point2 here = here();
        for (double ring = 1; ring <= 60; ring += 1) {
            int points = (int) Math.max(8, Math.ceil(2 * Math.PI * ring / 1.5));
            Point2 best = null;
            for (int k = 0; k < points; k++) {
                double angle = 2 * Math.PI * k / points;
                Point2 p = new Point2(here.x() + ring * Math.cos(angle), here.z() + ring * Math.sin(angle));
                if (memory.bounds().contains(p.x(), p.z()) && !memory.conduct().forbids(p)
                        && planner.standable(p, 0.1)) {
                    best = p;
                    break;
                }
            }
            if (best != null) {
                return Optional.of(best);
            }
        }
        return Optional.empty();
    }

    /** Where the agent stands. */
    Point2 here() {
        return motor.position();
    }

    /** Stops walking, if it walks. */
    void standStill() {
        if (motor.walking()) {
            motor.halt();
        }
    }

    /**
     * A free spot next to a thing of radius {@code size} at {@code centre}, on the side facing the
     * agent if that side is free, else around it; empty when there is none known.
     */
    Optional<Point2> besides(Point2 centre, double size) {
        Point2 here = here();
        double distance = size + memory.radius() + 0.6;
        double towards = Math.atan2(here.z() - centre.z(), here.x() - centre.x());
        for (double turn : List.of(0.0, 0.5, -0.5, 1.0, -1.0, 1.6, -1.6, 2.2, -2.2, Math.PI)) {
            Point2 spot = new Point2(centre.x() + distance * Math.cos(towards + turn),
                    centre.z() + distance * Math.sin(towards + turn));
            if (memory.bounds().contains(spot.x(), spot.z()) && !planner.offLimits(spot)
                    && planner.standable(spot, 0.1)) {
                return Optional.of(spot);
            }
        }
        return Optional.empty();
    }
}
