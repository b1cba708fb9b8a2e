package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.Reference;
import io.orchard.agents.map.Bearings;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;

/**
 * Turning on the spot: by an angle, to a compass direction, or to face an object. An object not
 * known is looked for by turning round in steps, as one looks about.
 */
final class Turning implements Pursuit {

    private static final double LOOK_STEP = Math.toRadians(60);

    private final Kit kit;
    private final Double angle;
    private final Reference target;
    private double heading = Double.NaN;
    private int looks;
    private String outcome = "";

    private Turning(Kit kit, @Nullable Double heading, @Nullable Double angle, @Nullable Reference target) {
        this.kit = kit;
        this.angle = angle;
        this.target = target;
        if (heading != null) {
            this.heading = heading;
        }
    }

    /** Turns by {@code radians}, positive to the left. */
    static Turning by(Kit kit, double radians) {
        return new Turning(kit, null, radians, null);
    }

    /** Turns to face a compass direction. */
    static Turning toward(Kit kit, Sector direction) {
        return new Turning(kit, heading(direction), null, null);
    }

    /** Turns to face an object, the one chosen or the one the words mean. */
    static Turning at(Kit kit, Reference target, @Nullable Known chosen) {
        Turning turning = new Turning(kit, null, null, target);
        if (chosen != null) {
            turning.heading = Bearings.headingTowards(kit.here(), chosen.where());
        }
        return turning;
    }

    /** The heading of a compass direction: north is 0, and headings grow to the left (west). */
    static double heading(Sector direction) {
        return Bearings.normalise(-Math.toRadians(45.0 * direction.ordinal()));
    }

    @Override
    public Status step() {
        kit.standStill();
        if (Double.isNaN(heading) && angle != null) {
            heading = Bearings.normalise(kit.motor.heading() + angle);
        }
        if (Double.isNaN(heading)) {
            Grounding grounding = kit.grounder.ground(target);
            Point2 here = kit.here();
            if (grounding instanceof Grounding.Found found) {
                kit.mention(found.chosen());
                heading = Bearings.headingTowards(here, found.chosen().where());
            } else if (grounding instanceof Grounding.Ambiguous ambiguous) {
                heading = Bearings.headingTowards(here, ambiguous.choices().get(0).where());
            } else if (looks++ < 6) {
                kit.motor.turnTo(Bearings.normalise(kit.motor.heading() + LOOK_STEP));
                return Status.RUNNING;
            } else {
                outcome = kit.speech.lookedAllAround(target);
                return Status.FAILED;
            }
        }
        kit.motor.turnTo(heading);
        outcome = kit.speech.facing(compass(heading));
        return Status.DONE;
    }

    @Override
    public String outcome() {
        return outcome;
    }

    /** The compass direction of a heading, in words: "north-east". */
    static String compass(double heading) {
        Point2 origin = new Point2(0, 0);
        return Grounder.compass(origin, Bearings.ahead(origin, heading, 1));
    }
}
