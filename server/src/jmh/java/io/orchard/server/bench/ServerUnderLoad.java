package io.orchard.server.bench;

/**
 * The world server the load generator measures: in its own JVM ({@link InlineServer}) or in a
 * process of its own ({@link ServerProcess}), which can be pinned to other cores than the clients.
 */
interface ServerUnderLoad extends AutoCloseable {

    /** The port it listens on, on loopback. */
    int port();

    /** Starts a measured window: tick statistics and CPU count from now. */
    void startWindow();

    /** The figures of the window started last. */
    ServerFigures endWindow();

    @Override
    void close() throws Exception;
}
