package io.orchard.cluster.node;

import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.order.SessionRef;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.protocol.MessageCodec;
import io.orchard.protocol.message.ClientMessage;
import io.orchard.protocol.message.GraspRequestMessage;
import io.orchard.protocol.message.ServerMessage;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.MissedTurn;
import io.orchard.server.sim.PartialSimulation.Claim;
import io.orchard.server.sim.Phase;
import io.orchard.server.sim.Recorder.Audience;

/**
 * The forms in which what parcels take and say travels between nodes: the protocol's messages as
 * the protocol's own lines ({@link MessageCodec}), everything else as plain records.
 */
final class Wire {

    private static final MessageCodec CODEC = new MessageCodec();

    private Wire() {}

    /**
     * A {@link KeyedLine}, its messages as lines of the protocol.
     *
     * @param key     its place
     * @param tick    its tick
     * @param time    its time
     * @param to      its audience, or null
     * @param client  the label of its client
     * @param message the message as recorded, or null
     * @param missed  the missed turn, or null
     * @param target  the client it goes to, or null
     * @param sent    the message as sent to it, or null
     */
    record Line(LineKey key, long tick, double time, Audience to, String client, String message, MissedTurn missed,
                SessionRef target, String sent) {

        static Line of(KeyedLine line) {
            return new Line(line.key(), line.tick(), line.time(), line.to(), line.client(),
                    line.message() == null ? null : CODEC.encode(line.message()), line.missed(), line.target(),
                    line.sent() == null ? null : CODEC.encode(line.sent()));
        }

        KeyedLine line() {
            return new KeyedLine(key, tick, time, to, client, message == null ? null : CODEC.decode(message), missed,
                    target, sent == null ? null : (ServerMessage) CODEC.decode(sent));
        }
    }

    /**
     * A {@link Parcel.Act}, its message as a line of the protocol.
     *
     * @param key     its place
     * @param session its client
     * @param message the message
     * @param phase   the game's phase when it is applied
     */
    record Act(LineKey key, SessionRef session, String message, Phase phase) {

        static Act of(Parcel.Act act) {
            return new Act(act.key(), act.session(), CODEC.encode(act.message()), act.phase());
        }

        Parcel.Act act() {
            return new Parcel.Act(key, session, (ClientMessage) CODEC.decode(message), phase);
        }
    }

    /**
     * A grasp with its place, its request as a line of the protocol.
     *
     * @param key     the place of the request
     * @param agent   the grasping agent
     * @param request the request
     * @param owner   the grasping agent's client, or null where it is not needed
     * @param label   that client's label, or null
     */
    record Grasp(LineKey key, AgentHandover agent, String request, SessionRef owner, String label) {

        static Grasp of(Parcel.KeyedClaim claim) {
            return new Grasp(claim.key(), claim.claim().agent(), CODEC.encode(claim.claim().message()), null, null);
        }

        static Grasp of(Parcel.ClaimOf claim) {
            return new Grasp(null, claim.claim().agent(), CODEC.encode(claim.claim().message()), claim.owner(),
                    claim.label());
        }

        private Claim claim() {
            return new Claim(agent, (GraspRequestMessage) CODEC.decode(request));
        }

        Parcel.KeyedClaim keyed() {
            return new Parcel.KeyedClaim(key, claim());
        }

        Parcel.ClaimOf claimOf() {
            return new Parcel.ClaimOf(claim(), owner, label);
        }
    }
}
