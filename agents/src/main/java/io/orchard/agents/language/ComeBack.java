package io.orchard.agents.language;

/**
 * Come back: "come back", "return", "go back", "come here", "go home". The person has no body in
 * the world, so "back" means where the agent set out from: the place where it stood when it was
 * given the instruction before this one (or where it entered the world, if there was none).
 */
public record ComeBack() implements Goal {
}
