package io.orchard.agents.goal;

import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Point2;
import java.util.Locale;

/**
 * Something a person asks an agent to do. An agent pursues an instructed goal in its own way and
 * returns to its autonomy when the goal is done.
 */
public sealed interface Goal permits Goal.GoTo, Goal.Collect, Goal.Explore, Goal.Stop, Goal.CarryOn {

    /** The goal in a few words, for the agent's answers ("go to (10, -20)"). */
    String describe();

    /**
     * Go to a point on the ground.
     *
     * @param target where to go
     */
    record GoTo(Point2 target) implements Goal {
        @Override
        public String describe() {
            return String.format(Locale.ROOT, "go to (%.1f, %.1f)", target.x(), target.z());
        }
    }

    /**
     * Collect a fruit: a named one, one of a kind, or any.
     *
     * @param kind    the kind wanted; null for any kind
     * @param fruitId the fruit wanted; null for any of the kind
     */
    record Collect(@Nullable FruitKind kind, @Nullable String fruitId) implements Goal {

        /** Collect any fruit. */
        public static Collect any() {
            return new Collect(null, null);
        }

        @Override
        public String describe() {
            if (fruitId != null) {
                return "collect " + fruitId;
            }
            return kind == null ? "collect a fruit" : "collect a " + kind.wireName();
        }
    }

    /** Explore what has not been seen. */
    record Explore() implements Goal {
        @Override
        public String describe() {
            return "explore";
        }
    }

    /** Stop and wait: no autonomy until told to carry on. */
    record Stop() implements Goal {
        @Override
        public String describe() {
            return "stop";
        }
    }

    /** Drop the instructed goal and carry on autonomously. */
    record CarryOn() implements Goal {
        @Override
        public String describe() {
            return "carry on";
        }
    }
}
