package io.orchard.cluster.node;

import com.fasterxml.jackson.annotation.JsonTypeInfo;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.parcel.OwnedAgent;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.cluster.parcel.PathQuery;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.FirstContact;
import java.util.List;

/**
 * What the tick asks a parcel entity ({@link ParcelEntity}) to do, one command per step, each
 * answered ({@link ParcelReply}) to the actor {@code replyTo} names (in Pekko's serialization format
 * of actor references), so that the tick knows when every parcel has done its part. The tick
 * numbers its steps ({@link Step}), so that a step asked again is answered again, not done twice.
 */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, include = JsonTypeInfo.As.PROPERTY, property = "kind")
public sealed interface ParcelCommand extends ClusterMessage {

    /** The actor the answer goes to, as Pekko's {@code ActorRefResolver} writes it. */
    String replyTo();

    /**
     * A command as a step of the tick, numbered. A parcel does a step once: the same step again is
     * answered with the answer it had, which moves with the parcel between nodes. The tick asks
     * again when an answer is late, because Pekko drops the commands it had buffered for a parcel
     * in the middle of a move between nodes.
     *
     * @param number  the step's number, never the same for two steps of a cluster's life
     * @param command what to do
     */
    record Step(long number, ParcelCommand command) implements ParcelCommand {
        @Override
        public String replyTo() {
            return command.replyTo();
        }
    }

    /** Take these agents as own; answered {@link ParcelReply.Done}. */
    record Own(List<OwnedAgent> agents, String replyTo) implements ParcelCommand {}

    /** Give up these own agents; answered {@link ParcelReply.Released}. */
    record Release(List<String> names, String replyTo) implements ParcelCommand {}

    /** Hold these ghosts too; answered {@link ParcelReply.Done}. */
    record AddGhosts(List<OwnedAgent> ghosts, String replyTo) implements ParcelCommand {}

    /** Forget the ghosts of these agents, which left the game; answered {@link ParcelReply.Done}. */
    record ForgetGhosts(List<String> names, String replyTo) implements ParcelCommand {}

    /** Hold these ghosts and no other, then the perceptions due at {@code tick}; answered {@link ParcelReply.Said}. */
    record Perceive(long tick, double time, List<OwnedAgent> ghosts, String replyTo) implements ParcelCommand {}

    /** The first own agent on each path; answered {@link ParcelReply.Contacts}. */
    record FirstAlong(List<PathQuery> paths, String replyTo) implements ParcelCommand {}

    /**
     * A path's first contact, as the parcels along it answered.
     *
     * @param path    the path
     * @param contact its first contact
     */
    record PathAnswer(PathQuery path, FirstContact contact) {}

    /** Apply these messages of the tick, in order; answered {@link ParcelReply.Applied}. */
    record Apply(long tick, double time, List<Wire.Act> acts, List<PathAnswer> answers, String replyTo)
            implements ParcelCommand {}

    /**
     * The place of a fruit's first claim, where all its grasp's lines go.
     *
     * @param fruit the fruit
     * @param key   the place
     */
    record FirstClaim(String fruit, LineKey key) {}

    /** Decide these grasps of own fruit, in order; answered {@link ParcelReply.Grasped}. */
    record Grasp(long tick, double time, List<Wire.Grasp> claims, List<FirstClaim> firstClaims, String replyTo)
            implements ParcelCommand {}

    /** Forget fruit taken in the halo; answered {@link ParcelReply.Done}. */
    record FruitTaken(List<String> fruit, String replyTo) implements ParcelCommand {}

    /** Hold these ghosts and no other, then walk the own agents to {@code time}; answered {@link ParcelReply.Walked}. */
    record Walk(long tick, double time, List<OwnedAgent> ghosts, String replyTo) implements ParcelCommand {}

    /** Put own agents where they were walked with others; answered {@link ParcelReply.Done}. */
    record PutWalked(List<AgentHandover> agents, String replyTo) implements ParcelCommand {}

    /**
     * Start a game anew: no agents, and of the world as made only this fruit; answered
     * {@link ParcelReply.Done}.
     */
    record Reset(List<String> fruitLeft, String replyTo) implements ParcelCommand {}

    /**
     * The parcel's node leaves (Pekko's hand-off): the parcel gives all it holds to the keeper, which
     * keeps it for the parcel's next start on another node, and then stops. Answered to no one.
     */
    record HandOff() implements ParcelCommand {
        @Override
        public String replyTo() {
            return null;
        }
    }

    /** The keeper kept the parcel's state: it stops. */
    record Kept() implements ParcelCommand {
        @Override
        public String replyTo() {
            return null;
        }
    }

    /**
     * What the keeper had of the parcel when it started here: the state, or null for none, and its
     * last step's number and answer (0 and null for none).
     */
    record Restored(Parcel.State state, long lastStep, ParcelReply lastReply) implements ParcelCommand {
        @Override
        public String replyTo() {
            return null;
        }
    }
}
