package io.orchard.cluster.node;

/**
 * Every message the cluster's actors send each other: what {@link ClusterSerializer} carries between
 * nodes (Pekko's configuration binds this type to it).
 */
public interface ClusterMessage {}
