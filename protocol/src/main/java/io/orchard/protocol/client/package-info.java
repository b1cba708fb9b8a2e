/**
 * A small blocking client connection on the JDK alone, shared by agents and viewers so that only
 * the server depends on Netty.
 */
package io.orchard.protocol.client;
