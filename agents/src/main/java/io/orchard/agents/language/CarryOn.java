package io.orchard.agents.language;

/**
 * Return to autonomy: "carry on", "continue", "as you were", "do your thing". The agent forgets any
 * instructed goal and pursues its own again, as it does when no one directs it.
 */
public record CarryOn() implements Goal {
}
