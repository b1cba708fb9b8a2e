package io.orchard.viewer.model.event;

/**
 * A node that takes part in the event graph at run time: it receives events that ROUTEs deliver
 * and sends its own through the cascade it is handed.
 */
public interface LiveNode {

    /**
     * Receives {@code value} at the field an event arrives at (the schema's name: an eventIn
     * such as {@code set_fraction} or an exposed field such as {@code translation}).
     */
    void receive(String field, Object value, EventGraph.Cascade cascade);
}
