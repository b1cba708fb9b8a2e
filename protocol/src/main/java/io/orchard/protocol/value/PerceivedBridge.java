package io.orchard.protocol.value;

/**
 * A bridge as a landmark, given as in the paper by its two entry points and its width.
 *
 * @param id     the bridge's id ({@code B1} or {@code B2})
 * @param entryA one entry point, relative to the agent
 * @param entryB the other entry point, on the far bank, relative to the agent
 * @param width  the width of the bridge deck
 */
public record PerceivedBridge(String id, RelativePosition entryA, RelativePosition entryB, double width) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public PerceivedBridge {
        Checks.id(id, "id");
        Checks.present(entryA, "entryA");
        Checks.present(entryB, "entryB");
        Checks.positive(width, "width");
    }
}
