/**
 * The network layer: a Netty TCP server speaking newline-delimited JSON. Each pipeline stage is its
 * own small class, in the order a line meets them: admission (the connection cap), the idle
 * timeout, the line deadline (against lines trickled forever), framing, the flood guard, decoding,
 * and the session with its handshake; encoding sits at the head for what goes out. The initializer
 * only assembles them. Decoded messages are handed to the simulation's inbox; what the simulation
 * sends a client during a tick is encoded and written once, on the client's I/O thread.
 */
package io.orchard.server.net;
