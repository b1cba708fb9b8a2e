/**
 * Scenario files: a world written down as JSON, so that a teacher can set up a particular garden
 * (a fruit just out of reach, a bridge too narrow for the big agents) and replay it. A
 * {@link io.orchard.server.world.scenario.Scenario} is the file's content as protocol value
 * records; {@link io.orchard.server.world.scenario.ScenarioFile} reads and writes it and refuses a
 * malformed file with a {@link io.orchard.server.world.scenario.ScenarioException} that names the
 * object and the problem. Whether the things in a well-formed file fit together (nothing overlaps,
 * the bridges span the river) is checked when a world is made from it, by
 * {@code World.fromScenario}. The format is documented in {@code docs/scenarios.md}.
 */
package io.orchard.server.world.scenario;
