package io.orchard.server.bench;

import io.orchard.server.WorldServer;
import io.orchard.server.sim.TickStats;

/** The server in the load generator's own JVM: its threads are told apart from the clients' by their names. */
final class InlineServer implements ServerUnderLoad {

    private final WorldServer server;
    private ThreadCpu start;

    InlineServer(WorldServer server) {
        this.server = server;
    }

    @Override
    public int port() {
        return server.port();
    }

    @Override
    public void startWindow() {
        server.resetTickStats();
        start = ThreadCpu.now();
    }

    @Override
    public ServerFigures endWindow() {
        TickStats ticks = server.tickStats();
        ThreadCpu.Used used = ThreadCpu.now().since(start);
        return new ServerFigures(ticks.ticks(), ticks.p50().toNanos() / 1e6, ticks.p99().toNanos() / 1e6,
                ticks.max().toNanos() / 1e6, ticks.lateTicks(), used.tick(), used.io(), Double.NaN);
    }

    @Override
    public void close() {
        server.close();
    }
}
