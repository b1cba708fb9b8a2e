/**
 * The parcels as Apache Pekko sharded entities: their commands, the serializer that carries them
 * between nodes, and the {@link io.orchard.cluster.game.Parcels} that reaches them.
 */
package io.orchard.cluster.node;
