/**
 * The messages of the Orchard protocol, named as in the paper (RegisterMessage,
 * GraspRequestMessage, PerceptionMessage...) plus what a networked system needs beside them:
 * the handshake, errors, results of actions, the clock, the game's lifecycle, instructions and
 * speech, and the updates that drive viewers in place of the paper's EAI calls.
 */
package io.orchard.protocol.message;
