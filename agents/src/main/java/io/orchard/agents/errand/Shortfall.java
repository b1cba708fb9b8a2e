package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.RelativeMove;
import io.orchard.agents.map.Bearings;
import io.orchard.protocol.value.Point2;

/**
 * Walking so far in a direction ("head north for 15 metres") when the point it leads to is where
 * the agent cannot stand: in the river or beyond the world's edge. The agent says why in the
 * world's terms, and how far it can go that way, and goes as far as that: "That point is in the
 * river; the nearest dry place that way is 9 metres north, and I'll go there."
 */
final class Shortfall {

    /** How close to the water's edge, or the world's, the agent stops short. */
    private static final double CLEARANCE = 1;

    private static final double STEP = 0.5;

    private Shortfall() {
    }

    /** The pursuit of walking {@code distance} units along {@code heading}, named {@code direction}. */
    static Pursuit walk(Kit kit, double heading, double distance, String direction) {
        Point2 here = kit.here();
        Point2 target = Bearings.ahead(here, heading, distance);
        String problem = problem(kit, target);
        if (problem == null) {
            return WalkPursuit.to(kit, target, "Done: I went " + RelativeMove.metres(distance) + " " + direction + ".");
        }
        double reach = distance;
        while (reach > 0 && problem(kit, Bearings.ahead(here, heading, reach)) != null) {
            reach -= STEP;
        }
        reach -= CLEARANCE;
        if (reach < CLEARANCE) {
            return failed("That point is " + problem + ", and I can't go any way " + direction + " from here; I stayed "
                    + "where I am.");
        }
        String dry = RelativeMove.metres(Math.floor(reach)) + " " + direction;
        kit.motor.say("That point is " + problem + "; the nearest place I can stand that way is " + dry
                + ", and I'll go there.");
        return WalkPursuit.to(kit, Bearings.ahead(here, heading, reach), "Done: I went " + dry + ", not the "
                + RelativeMove.metres(distance) + " you asked: further is " + problem + ".");
    }

    /** Why the agent cannot stand at this point, in the world's words; null when it can, as far as it knows. */
    static String problem(Kit kit, Point2 p) {
        if (!kit.memory.bounds().contains(p.x(), p.z())) {
            return "beyond the edge of the world";
        }
        if (kit.memory.river().water(p.x(), p.z(), kit.memory.radius())) {
            return "in the river";
        }
        return kit.forbidden(p).map(rule -> "against " + rule).orElse(null);
    }

    private static Pursuit failed(String why) {
        return new Pursuit() {
            @Override
            public Status step() {
                return Status.FAILED;
            }

            @Override
            public String outcome() {
                return why;
            }
        };
    }
}
