package io.orchard.cluster.node;

import com.fasterxml.jackson.annotation.JsonTypeInfo;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.FirstContact;
import java.util.List;

/**
 * A parcel entity's answer to a {@link ParcelCommand}. Its kind travels with it, because a parcel's
 * last answer moves between nodes with the parcel ({@link ParcelCommand.Step}).
 */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, include = JsonTypeInfo.As.PROPERTY, property = "kind")
public sealed interface ParcelReply extends ClusterMessage {

    /** Done, with nothing to say. */
    record Done() implements ParcelReply {}

    /** The lines said. */
    record Said(List<Wire.Line> lines) implements ParcelReply {}

    /** The first contact on each path asked about, in order; null for a path that meets none. */
    record Contacts(List<FirstContact> contacts) implements ParcelReply {}

    /** The own agents given up, as they were. */
    record Released(List<AgentHandover> agents) implements ParcelReply {}

    /**
     * The lines said applying the tick's messages, the grasps asked for, the own agents after, and
     * the agents that unregistered.
     */
    record Applied(List<Wire.Line> lines, List<Wire.Grasp> claims, List<AgentHandover> owned, List<String> removed)
            implements ParcelReply {}

    /** The lines said deciding the grasps, and the fruit taken. */
    record Grasped(List<Wire.Line> lines, List<Parcel.Taken> taken) implements ParcelReply {}

    /** The lines said walking, the agents left to be walked with others, and the own agents after. */
    record Walked(List<Wire.Line> lines, List<AgentHandover> left, List<AgentHandover> owned) implements ParcelReply {}
}
