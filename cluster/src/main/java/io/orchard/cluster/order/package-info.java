/**
 * The single server's order of a tick, which the parts of a split world keep: every line a part
 * records or sends carries a {@link io.orchard.cluster.order.LineKey}, and lines from many parts
 * are merged by key.
 */
package io.orchard.cluster.order;
