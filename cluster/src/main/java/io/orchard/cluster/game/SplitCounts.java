package io.orchard.cluster.game;

/**
 * How much of a split game crossed parcels' borders: what the parcels' halos and the hand-overs are
 * for, counted so that a test can tell that it happened.
 *
 * @param handOvers              agents that walked from one parcel into another
 * @param sightingsAcrossBorders agents perceived standing in another parcel than the perceiver's
 * @param graspsAcrossBorders    grasps of fruit in another parcel than the grasping agent's
 * @param pathsBeyondHalo        moves whose path left the mover's parcel's halo, so that the parcels
 *                               along it were asked for contacts
 * @param walkedTogether         agents walked together with agents of other parcels, as they could
 *                               touch across a border
 */
public record SplitCounts(long handOvers, long sightingsAcrossBorders, long graspsAcrossBorders,
                          long pathsBeyondHalo, long walkedTogether) {
}
