/**
 * The network layer: a Netty TCP server speaking newline-delimited JSON. Each pipeline stage is its
 * own small class (framing, flood guard, decoding, encoding, the session and its handshake); the
 * initializer only assembles them. Decoded messages are handed to the simulation's inbox.
 */
package io.orchard.server.net;
