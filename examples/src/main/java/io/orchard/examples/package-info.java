/**
 * Runnable programs built on the other modules. {@link io.orchard.examples.Orchard} is the
 * {@code ./orchard} launcher; each of its subcommands is a picocli command listed in
 * {@code Orchard.commands}: the server's, the viewer's and the agents' come from their modules, the
 * others live in the package of what they run.
 */
package io.orchard.examples;
