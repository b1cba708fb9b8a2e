package io.orchard.protocol.value;

/**
 * A bridge across the river, represented as in the paper by its two entry points and its width.
 *
 * @param id     the bridge's id
 * @param entryA the entry point on one bank
 * @param entryB the entry point on the other bank
 * @param width  the width of the deck
 */
public record BridgeShape(String id, Point2 entryA, Point2 entryB, double width) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public BridgeShape {
        Checks.id(id, "id");
        Checks.present(entryA, "entryA");
        Checks.present(entryB, "entryB");
        Checks.positive(width, "width");
        if (entryA.equals(entryB)) {
            throw new IllegalArgumentException("bridge " + id + " must have two different entry points");
        }
    }
}
