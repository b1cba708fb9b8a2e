/**
 * The network layer: a Netty TCP server speaking newline-delimited JSON. Each pipeline stage is its
 * own small class, in the order a line meets them: admission (the connection cap), the deadline for
 * the {@code Hello} (with the cap on connections waiting to send it), the idle timeout (agents
 * only), the line deadline (against lines trickled forever), the gate for large lines, framing, the
 * flood guard, decoding, and the session with its handshake; encoding sits at the head for what
 * goes out. The initializer only assembles them. Decoded messages are handed to the simulation's
 * inbox; what the simulation sends a client during a tick is encoded once, on the client's I/O
 * thread, and waits in the client's outbox until its socket takes it. Models are kept once for all
 * clients ({@code ModelStore}).
 */
package io.orchard.server.net;
