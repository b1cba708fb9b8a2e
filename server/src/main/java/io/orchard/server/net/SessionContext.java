package io.orchard.server.net;

import io.orchard.server.sim.Inbox;
import java.util.concurrent.atomic.AtomicLong;

/**
 * What every session of one server shares: the simulation it talks to, the limits, the secret, and
 * the server-wide state behind the limits (the models held, the output waiting, the writes of a
 * tick). Made once by the initializer.
 *
 * @param inbox      the simulation
 * @param token      the shared secret clients must present, or null
 * @param limits     the limits
 * @param sessionIds where session numbers come from
 * @param writes     the writes of a tick, by I/O thread
 * @param models     the models held
 * @param budget     the output waiting for all clients
 */
record SessionContext(Inbox inbox, String token, NetLimits limits, AtomicLong sessionIds, TickWrites writes,
                      ModelStore models, OutputBudget budget) {

    /** A context for a server with these limits and no session yet. */
    static SessionContext of(Inbox inbox, String token, NetLimits limits) {
        return new SessionContext(inbox, token, limits, new AtomicLong(), new TickWrites(),
                new ModelStore(limits.modelBytesInAll()), new OutputBudget(limits.maxPendingBytesInAll()));
    }
}
