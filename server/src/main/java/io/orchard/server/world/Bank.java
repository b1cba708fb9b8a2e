package io.orchard.server.world;

/**
 * The two banks of the river, named by compass direction so that people and agents can talk about
 * them ("the fruit is on the south bank"). A river that runs mostly east-west has a north and a
 * south bank; one that runs mostly north-south has a west and an east bank. Which pair a world
 * uses follows from where the centres of the two pieces of land lie.
 */
public enum Bank {
    /** The bank towards -z. */
    NORTH,
    /** The bank towards +z. */
    SOUTH,
    /** The bank towards +x. */
    EAST,
    /** The bank towards -x. */
    WEST;

    /** The word people use: "north bank". */
    public String label() {
        return name().toLowerCase(java.util.Locale.ROOT) + " bank";
    }
}
