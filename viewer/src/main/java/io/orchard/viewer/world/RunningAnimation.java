package io.orchard.viewer.world;

/**
 * An animation (a TimeSensor, or a glTF clip) an agent started and has not stopped.
 *
 * @param name      the time sensor's name
 * @param loop      whether it repeats until stopped
 * @param startTime the simulated time it started
 */
public record RunningAnimation(String name, boolean loop, double startTime) {
}
