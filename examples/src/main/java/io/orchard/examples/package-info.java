/**
 * Runnable programs built on the other modules. {@link io.orchard.examples.Orchard} is the
 * {@code ./orchard} launcher; each of its subcommands is a {@link io.orchard.examples.Command}
 * listed in {@code Orchard.COMMANDS}, and lives in the package of what it runs.
 */
package io.orchard.examples;
