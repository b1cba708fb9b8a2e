package io.orchard.agents.errand;

import io.orchard.agents.behaviour.Status;
import io.orchard.agents.language.RelativeMove;
import io.orchard.agents.map.Bearings;
import io.orchard.protocol.value.Point2;
import java.util.function.DoubleFunction;

/**
 * Walking so far in a direction ("head north for 15 metres") when the point it leads to is where
 * the agent cannot stand: in the river or beyond the world's edge. The agent says why in the
 * world's terms, and how far it can go that way, and goes as far as that: "That point is in the
 * river; the nearest dry place that way is 9 metres north, and I'll go there." When its way turns
 * out blocked on the way, by something it did not know of, it says how far it went.
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
            return WalkPursuit.measured(kit, target, kit.speech.went(kit.speech.metres(RelativeMove.metres(distance),
                    direction)), blocked(kit, distance, direction));
        }
        double reach = distance;
        while (reach > 0 && problem(kit, Bearings.ahead(here, heading, reach)) != null) {
            reach -= STEP;
        }
        reach -= CLEARANCE;
        if (reach < CLEARANCE) {
            return failed(kit.speech.pointNowhere(problem, direction));
        }
        String dry = kit.speech.metres(RelativeMove.metres(Math.floor(reach)), direction);
        kit.motor.say(kit.speech.pointNearest(problem, dry));
        return WalkPursuit.measured(kit, Bearings.ahead(here, heading, reach), kit.speech.wentShort(dry,
                kit.speech.metres(RelativeMove.metres(distance)), problem), blocked(kit, distance, direction));
    }

    /** What the agent says when its way turns out blocked, given how far it went. */
    private static DoubleFunction<String> blocked(Kit kit, double distance, String direction) {
        return went -> kit.speech.blockedShort(kit.speech.metres(RelativeMove.metres(Math.floor(went)), direction),
                kit.speech.metres(RelativeMove.metres(distance)));
    }

    /** Why the agent cannot stand at this point, in the world's words; null when it can, as far as it knows. */
    static String problem(Kit kit, Point2 p) {
        if (!kit.memory.bounds().contains(p.x(), p.z())) {
            return kit.speech.beyondTheEdge();
        }
        if (kit.memory.river().water(p.x(), p.z(), kit.memory.radius())) {
            return kit.speech.inTheRiver();
        }
        return kit.forbidden(p).map(kit.speech::against).orElse(null);
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
