package io.orchard.agents;

import io.orchard.agents.map.Bearings;
import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.PerceivedRiver;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RelativePosition;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Vec3;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Predicate;

/**
 * One tick's perception, the paper's three messages in one: where the agent stands and faces, the
 * trees, tables and agents in view (relative: distance, and bearing from the heading, positive to
 * the left), the fruit in view (absolute), the river and bridges in view and the castle's compass
 * sector.
 */
public final class Perception {

    private final PerceptionMessage seen;
    private final LandmarkPerceptionMessage landmarks;
    private final CastlePerceptionMessage castle;

    /** The perception of one tick; the landmark and castle parts may be null when they did not come. */
    public Perception(PerceptionMessage seen, @Nullable LandmarkPerceptionMessage landmarks,
                      @Nullable CastlePerceptionMessage castle) {
        this.seen = Objects.requireNonNull(seen, "perception");
        this.landmarks = landmarks;
        this.castle = castle;
    }

    /** The tick it was computed in. */
    public long tick() {
        return seen.tick();
    }

    /** Where the agent stands: the {@code from} of its next move. */
    public Vec3 position() {
        return seen.position();
    }

    /** Where the agent stands, on the ground. */
    public Point2 ground() {
        return seen.position().onGround();
    }

    /** The agent's heading. */
    public double heading() {
        return seen.heading();
    }

    /** Trees and tables in view. */
    public List<PerceivedObject> objects() {
        return seen.objects();
    }

    /** Other agents in view. */
    public List<PerceivedAgent> agents() {
        return seen.agents();
    }

    /** Fruit in view, by absolute position. */
    public List<PerceivedFruit> fruit() {
        return seen.fruit();
    }

    /** The river, when in view. */
    public @Nullable PerceivedRiver river() {
        return landmarks == null ? null : landmarks.river();
    }

    /** The bridges in view. */
    public List<PerceivedBridge> bridges() {
        return landmarks == null ? List.of() : landmarks.bridges();
    }

    /** The compass sector the castle lies in; null if it did not come. */
    public @Nullable Sector castle() {
        return castle == null ? null : castle.sector();
    }

    /** Where a thing perceived at {@code at} is in the world. */
    public Point2 toWorld(RelativePosition at) {
        return Bearings.toWorld(ground(), heading(), at);
    }

    /** The nearest fruit in view that passes {@code filter}. */
    public Optional<PerceivedFruit> nearestFruit(Predicate<PerceivedFruit> filter) {
        Point2 here = ground();
        return seen.fruit().stream().filter(filter)
                .min(Comparator.comparingDouble(f -> f.position().onGround().distance(here)));
    }

    /** The perception message itself. */
    public PerceptionMessage message() {
        return seen;
    }

    /** The landmark perception of the same tick; null if it did not come. */
    public @Nullable LandmarkPerceptionMessage landmarks() {
        return landmarks;
    }

    /** The castle perception of the same tick; null if it did not come. */
    public @Nullable CastlePerceptionMessage castleMessage() {
        return castle;
    }
}
