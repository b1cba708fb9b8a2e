package io.orchard.agents.zoo;

import io.orchard.protocol.value.FruitState;
import io.orchard.protocol.value.Point2;
import io.orchard.server.world.World;
import java.util.List;
import java.util.Locale;

/**
 * Reads from a {@link Recording} how long an agent went without progress while it had fruit to
 * collect.
 *
 * <p><b>Reachable fruit</b>: a fruit still in the world whose centre is within the agent's gripper
 * heights (with room for perception's rounding) and to which a walk leads in the recorded world
 * ({@link WalkingDistances}: the server's own geometry, around trees, tables and the castle, over
 * the river only by a bridge). The walk is measured on the whole world, so a move the server
 * refused does not make a fruit unreachable: the agent is expected to go around, or choose
 * another fruit.
 *
 * <p><b>The agent's chosen fruit</b>: the test does not read the agent's mind. At the start of each
 * stretch it takes the reachable fruit nearest by walking distance among those the agent has
 * perceived (the nearest of all while it has perceived none), and keeps it until the next progress.
 *
 * <p><b>Progress</b>: the agent takes a fruit; or the walking distance to the chosen fruit shrinks by
 * at least {@value #STEP} unit; or, while some reachable fruit has not yet been perceived by the
 * agent, it looks at ground it has not looked at before ({@link Lookout}): it cannot choose a fruit
 * it has not seen, and exploring is how it gets to. An agent that stands still, or walks back and
 * forth over the same ground, makes none.
 *
 * <p><b>A stretch</b> without progress starts at the last progress (or the agent's joining, or the
 * last moment no fruit was reachable) and lasts while reachable fruit remains.
 */
final class Progress {

    /** How much nearer a walk must bring the agent to count. */
    static final double STEP = 1;

    private final Recording game;
    private final World world;
    private final WalkingDistances walks;

    Progress(Recording game) {
        this.game = game;
        this.world = game.model();
        this.walks = new WalkingDistances(world, game.body());
    }

    /**
     * The longest stretch without progress in the recording.
     *
     * @param from when it started
     * @param to when it ended: the next progress or the end of the recording
     * @param where where the agent stood at its end
     * @param chosen the fruit taken for the agent's choice
     * @param distance its walking distance then
     * @param reachable how many fruit were reachable then
     * @param refusals the moves refused during the stretch
     */
    record Stretch(double from, double to, Point2 where, String chosen, double distance, int reachable,
                   List<Recording.Refusal> refusals) {

        double seconds() {
            return to - from;
        }

        @Override
        public String toString() {
            return String.format(Locale.ROOT, "%.1f s without progress from %.2f s to %.2f s, at (%.1f, %.1f) with %d"
                    + " reachable fruit left, the chosen %s %.1f units' walk away; moves refused meanwhile: %s",
                    seconds(), from, to, where.x(), where.z(), reachable, chosen, distance, refusals);
        }
    }

    /** The longest stretch without progress while reachable fruit remained; null when there was none. */
    static Stretch longest(Recording game) {
        return new Progress(game).longest();
    }

    private Stretch longest() {
        Lookout lookout = new Lookout(world, game.body().sight());
        Stretch longest = null;
        Double since = null;
        String chosen = null;
        double reference = Double.POSITIVE_INFINITY;
        for (Recording.Tick tick : game.ticks()) {
            boolean looked = !Double.isNaN(tick.heading()) && lookout.look(tick.at(), tick.heading());
            int reachable = 0;
            int unseen = 0;
            String nearest = null;
            double nearestDistance = Double.POSITIVE_INFINITY;
            String nearestKnown = null;
            double nearestKnownDistance = Double.POSITIVE_INFINITY;
            double chosenDistance = Double.POSITIVE_INFINITY;
            for (FruitState fruit : game.world().fruit()) {
                if (!game.left(fruit.id(), tick)) {
                    continue;
                }
                double d = walks.to(fruit, tick.at());
                if (d == Double.POSITIVE_INFINITY) {
                    continue;
                }
                reachable++;
                boolean known = game.known(fruit.id(), tick);
                unseen += known ? 0 : 1;
                if (d < nearestDistance) {
                    nearestDistance = d;
                    nearest = fruit.id();
                }
                if (known && d < nearestKnownDistance) {
                    nearestKnownDistance = d;
                    nearestKnown = fruit.id();
                }
                if (fruit.id().equals(chosen)) {
                    chosenDistance = d;
                }
            }
            boolean progress = tick.grasped() || chosenDistance <= reference - STEP || (looked && unseen > 0);
            if (since == null || progress || reachable == 0 || chosenDistance == Double.POSITIVE_INFINITY) {
                since = tick.time();
                // The agent's chosen fruit from here on: the nearest it has seen, else the nearest there is.
                chosen = nearestKnown != null ? nearestKnown : nearest;
                reference = nearestKnown != null ? nearestKnownDistance : nearestDistance;
                continue;
            }
            double length = tick.time() - since;
            if (longest == null || length > longest.seconds()) {
                double start = since;
                List<Recording.Refusal> refused = game.refusals().stream()
                        .filter(r -> r.time() >= start && r.time() <= tick.time()).toList();
                longest = new Stretch(since, tick.time(), tick.at(), chosen, chosenDistance, reachable, refused);
            }
        }
        return longest;
    }
}
