package io.orchard.cluster.game;

import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.parcel.OwnedAgent;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.cluster.parcel.ParcelId;
import io.orchard.cluster.parcel.PathQuery;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.FirstContact;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Every parcel of a split game, as its tick reaches them: one call per step of the tick, which
 * returns once every parcel concerned has done its part. Parcels without agents of their own take
 * part only when asked about their fruit or their agents on a path. The parcels may be objects of this JVM
 * ({@link LocalParcels}) or sharded entities of a cluster.
 */
public interface Parcels {

    /**
     * What the parcels said while applying the tick's messages, the grasps they were asked for, their
     * own agents as the actions left them, and the agents that unregistered.
     *
     * @param lines   their lines
     * @param claims  the grasps, each with the place of its request
     * @param owned   the own agents of the parcels that applied messages
     * @param removed the agents that unregistered
     */
    record Applied(List<KeyedLine> lines, List<Parcel.KeyedClaim> claims, List<AgentHandover> owned,
                   List<String> removed) {}

    /**
     * What the parcels said while deciding the grasps, and the fruit taken.
     *
     * @param lines their lines
     * @param taken the fruit taken, parcel by parcel
     */
    record Grasped(List<KeyedLine> lines, List<Parcel.Taken> taken) {}

    /**
     * What the parcels said while walking their agents, the agents they left to be walked with other
     * parcels' agents, and their own agents where they walked to.
     *
     * @param lines their lines
     * @param left  the agents left
     * @param owned the own agents of every parcel that has some
     */
    record Walked(List<KeyedLine> lines, List<AgentHandover> left, List<AgentHandover> owned) {}

    /**
     * Every parcel starts a game anew: no agents, and of the world as made only the fruit named
     * (all of it for a new game; what a saved game had left for one that goes on from it).
     */
    void reset(Set<String> fruitLeft);

    /** Each named parcel takes these agents as its own. */
    void own(Map<ParcelId, List<OwnedAgent>> agents);

    /** Each named parcel gives up these agents; returns them as they were. */
    List<AgentHandover> release(Map<ParcelId, List<String>> names);

    /** Each named parcel holds these ghosts too (agents that came into the game in the middle of a tick). */
    void addGhosts(Map<ParcelId, List<OwnedAgent>> ghosts);

    /** Each named parcel forgets the ghosts of these agents, which left the game. */
    void forgetGhosts(Map<ParcelId, List<String>> names);

    /**
     * The perceptions due at {@code tick}: every parcel named in {@code ghosts} (every parcel that has
     * agents of its own; the others need no ghosts) takes its ghosts anew, then perceives; returns
     * their lines.
     */
    List<KeyedLine> perceive(long tick, double time, Map<ParcelId, List<OwnedAgent>> ghosts);

    /** The first contact on each path, from the parcels named for it; null for a path that meets none. */
    Map<PathQuery, FirstContact> firstAlong(Map<ParcelId, List<PathQuery>> paths);

    /** Each named parcel applies its messages of the tick, in order, with the answers for paths beyond halos. */
    Applied apply(long tick, double time, Map<ParcelId, List<Parcel.Act>> acts, Map<PathQuery, FirstContact> answers);

    /** Each named parcel decides the grasps of its fruit, given in order, lines placed by {@code firstClaims}. */
    Grasped grasp(long tick, double time, Map<ParcelId, List<Parcel.ClaimOf>> claims, Map<String, LineKey> firstClaims);

    /** Each named parcel forgets fruit taken in its halo. */
    void fruitTaken(Map<ParcelId, List<String>> fruit);

    /**
     * Every parcel named in {@code ghosts} (every parcel that has agents of its own) takes its ghosts
     * anew, as the tick's actions left them, and walks its agents to simulated {@code time}.
     */
    Walked walk(long tick, double time, Map<ParcelId, List<OwnedAgent>> ghosts);

    /** Each named parcel puts its agents where they were walked together with others. */
    void walked(Map<ParcelId, List<AgentHandover>> agents);
}
