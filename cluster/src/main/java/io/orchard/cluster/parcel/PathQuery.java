package io.orchard.cluster.parcel;

import io.orchard.protocol.value.Vec3;

/**
 * A walker's path whose first contact with other agents the parcels along it are asked for, when it
 * leaves its own parcel's halo. A value, sent between nodes.
 *
 * @param walker the walking agent
 * @param from   where it walks from
 * @param to     where it walks to
 * @param radius its body's radius
 */
public record PathQuery(String walker, Vec3 from, Vec3 to, double radius) {}
