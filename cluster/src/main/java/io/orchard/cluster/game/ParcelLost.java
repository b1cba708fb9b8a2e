package io.orchard.cluster.game;

/**
 * A step of the tick got no answer from a parcel: the node that hosted it was lost, or the game is
 * being rolled back to its last checkpoint. What the parcels held can no longer be trusted.
 */
public final class ParcelLost extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /** A parcel did not answer, for this reason. */
    public ParcelLost(String message, Throwable cause) {
        super(message, cause);
    }
}
