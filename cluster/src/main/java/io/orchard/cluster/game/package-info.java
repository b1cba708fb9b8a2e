/**
 * A game whose world is cut into parcels: the tick's steps over the parcels and the merge of what
 * they say, in the single server's order.
 */
package io.orchard.cluster.game;
