package io.orchard.protocol.message;

import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.LeanAgent;
import io.orchard.protocol.value.LeanBridge;
import io.orchard.protocol.value.LeanFruit;
import io.orchard.protocol.value.LeanObject;
import io.orchard.protocol.value.LeanPoint;
import io.orchard.protocol.value.LeanRiver;
import io.orchard.protocol.value.LeanUnits;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Sector;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

/**
 * Everything an agent perceives in one tick, in one line: what {@link PerceptionMessage},
 * {@link LandmarkPerceptionMessage} and {@link CastlePerceptionMessage} carry, with lengths in whole
 * centimetres and angles in whole milliradians ({@link LeanUnits}) and every perceived thing as a
 * short array. The server sends it instead of those three to a client whose hello reads
 * {@code LeanPerception} ({@code io.orchard.protocol.value.Form}); {@link #toPerception()},
 * {@link #toLandmarks()} and {@link #toCastle()} give the three back, equal to the ordinary ones at
 * the precision the server rounds them to.
 *
 * @param tick     the tick it was computed in
 * @param agent    the perceiving agent
 * @param position the agent's own position, in centimetres
 * @param heading  the agent's own heading, in milliradians (3142 is π)
 * @param objects  trees and tables in view
 * @param agents   other agents in view
 * @param fruit    fruit in view
 * @param river    the river, when in view
 * @param bridges  bridges in view
 * @param castle   the compass sector the castle lies in
 */
public record LeanPerceptionMessage(long tick,
                                    String agent,
                                    LeanPoint position,
                                    long heading,
                                    List<LeanObject> objects,
                                    List<LeanAgent> agents,
                                    List<LeanFruit> fruit,
                                    @Nullable LeanRiver river,
                                    List<LeanBridge> bridges,
                                    Sector castle) implements ServerMessage {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public LeanPerceptionMessage {
        Checks.nonNegative(tick, "tick");
        Checks.name(agent, "agent");
        Checks.present(position, "position");
        objects = Checks.list(objects, "objects");
        agents = Checks.list(agents, "agents");
        fruit = Checks.list(fruit, "fruit");
        bridges = Checks.list(bridges, "bridges");
        Checks.present(castle, "castle");
    }

    /**
     * The lean form of one tick's perception.
     *
     * @throws IllegalArgumentException when the three are not of the same agent and tick
     */
    public static LeanPerceptionMessage of(PerceptionMessage seen, LandmarkPerceptionMessage landmarks,
                                           CastlePerceptionMessage castle) {
        if (!seen.agent().equals(landmarks.agent()) || !seen.agent().equals(castle.agent())
                || seen.tick() != landmarks.tick() || seen.tick() != castle.tick()) {
            throw new IllegalArgumentException("a lean perception is made of the three parts of one agent's perception"
                    + " of one tick, were of " + seen.agent() + " at " + seen.tick() + ", " + landmarks.agent() + " at "
                    + landmarks.tick() + " and " + castle.agent() + " at " + castle.tick());
        }
        return new LeanPerceptionMessage(seen.tick(), seen.agent(), LeanPoint.of(seen.position()),
                LeanUnits.milliradians(seen.heading()), map(seen.objects(), LeanObject::of),
                map(seen.agents(), LeanAgent::of), map(seen.fruit(), LeanFruit::of),
                landmarks.river() == null ? null : LeanRiver.of(landmarks.river()),
                map(landmarks.bridges(), LeanBridge::of), castle.sector());
    }

    /** The trees, tables, agents and fruit in view, as {@link PerceptionMessage} gives them. */
    public PerceptionMessage toPerception() {
        return new PerceptionMessage(tick, agent, position.toVec3(), LeanUnits.radians(heading),
                map(objects, LeanObject::toPerceived), map(agents, LeanAgent::toPerceived),
                map(fruit, LeanFruit::toPerceived));
    }

    /** The river and the bridges in view, as {@link LandmarkPerceptionMessage} gives them. */
    public LandmarkPerceptionMessage toLandmarks() {
        return new LandmarkPerceptionMessage(tick, agent, river == null ? null : river.toPerceived(),
                map(bridges, LeanBridge::toPerceived));
    }

    /** The castle's sector, as {@link CastlePerceptionMessage} gives it. */
    public CastlePerceptionMessage toCastle() {
        return new CastlePerceptionMessage(tick, agent, castle);
    }

    private static <A, B> List<B> map(List<A> from, Function<A, B> each) {
        List<B> to = new ArrayList<>(from.size());
        for (A a : from) {
            to.add(each.apply(a));
        }
        return to;
    }
}
