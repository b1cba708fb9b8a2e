package io.orchard.agents.language;

/**
 * Stop: "stop", "halt", "freeze", "stop following Guppy". The agent drops every goal, stands still
 * and stays idle until the next instruction; {@link CarryOn} returns it to autonomy.
 */
public record Stop() implements Goal {
}
