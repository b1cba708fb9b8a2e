package io.orchard.server.net;

import io.orchard.server.sim.Inbox;
import java.util.concurrent.atomic.AtomicLong;

/**
 * What every session of one server shares: the simulation it talks to, the limits, the secrets, and
 * the server-wide state behind the limits (the models held, the output waiting, the writes of a
 * tick). Made once by the initializer.
 *
 * @param inbox      the simulation
 * @param token      the shared secret clients must present, or null
 * @param operator   the operator's secret, which lets a client control the game, or null when no
 *                   client may
 * @param limits     the limits
 * @param sessionIds where session numbers come from
 * @param writes     the writes of a tick, by I/O thread
 * @param models     the models held
 * @param budget     the output waiting for all clients
 */
record SessionContext(Inbox inbox, Secret token, Secret operator, NetLimits limits, AtomicLong sessionIds, TickWrites writes,
                      ModelStore models, OutputBudget budget) {

    /** A context for a server with these limits, no operator and no session yet. */
    static SessionContext of(Inbox inbox, String token, NetLimits limits) {
        return of(inbox, token, null, limits);
    }

    /** A context for a server with these secrets and limits and no session yet. */
    static SessionContext of(Inbox inbox, String token, String operatorToken, NetLimits limits) {
        return new SessionContext(inbox, Secret.of(token), Secret.of(operatorToken), limits, new AtomicLong(), new TickWrites(),
                new ModelStore(limits.modelBytesInAll()), new OutputBudget(limits.maxPendingBytesInAll()));
    }
}
