/**
 * The values that protocol messages carry: coordinates and rotations, an agent's body, what an
 * agent perceives and how the world is described to viewers. Every value is an immutable record
 * whose constructor validates it, so an invalid value cannot exist.
 *
 * <p>Coordinates follow VRML: {@code y} is up, the ground is the X/Z plane, north is {@code -z}.
 */
package io.orchard.protocol.value;
