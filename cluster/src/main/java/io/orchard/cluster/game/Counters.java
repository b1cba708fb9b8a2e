package io.orchard.cluster.game;

/** The running counts behind {@link SplitCounts}; the game's thread's alone. */
final class Counters {

    long handOvers;
    long sightingsAcrossBorders;
    long graspsAcrossBorders;
    long pathsBeyondHalo;
    long walkedTogether;

    SplitCounts copy() {
        return new SplitCounts(handOvers, sightingsAcrossBorders, graspsAcrossBorders, pathsBeyondHalo,
                walkedTogether);
    }
}
