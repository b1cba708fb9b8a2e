/**
 * The world cut into square parcels, each owning the agents and fruit in its square and holding
 * ghosts of the agents within sight of it (its halo).
 */
package io.orchard.cluster.parcel;
