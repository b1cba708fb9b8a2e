/**
 * What the command lines of Orchard's programs share, on picocli alone: the
 * {@linkplain io.orchard.cli.CommandLineErrors handler} that answers a wrong command line with
 * {@code orchard <command>: <what is wrong>} and exit status 2, and converters of option values
 * ({@link io.orchard.cli.Whole}, {@link io.orchard.cli.Decimal}, {@link io.orchard.cli.Seed},
 * {@link io.orchard.cli.Port}) whose errors name the value and what was expected.
 */
package io.orchard.cli;
