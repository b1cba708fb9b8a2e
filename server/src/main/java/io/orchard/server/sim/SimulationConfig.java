package io.orchard.server.sim;

import io.orchard.protocol.value.ClockMode;
import java.time.Duration;

/**
 * How a simulation runs.
 *
 * @param tickRate          ticks per simulated second
 * @param clock             realtime or lockstep
 * @param timeLimit         the game's length in simulated seconds
 * @param waitFor           agents to wait for before the game starts; 0 starts at the first one
 * @param lockstepDeadline  in lockstep, how long (wall clock) a tick waits for slow agents
 * @param agentsPerSession  how many agents one connection may drive
 * @param bodyLimits        caps on agents' bodies
 */
public record SimulationConfig(int tickRate, ClockMode clock, double timeLimit, int waitFor,
                               Duration lockstepDeadline, int agentsPerSession, BodyLimits bodyLimits) {

    /** 20 ticks per second in realtime, 300 s games starting at the first agent. */
    public static final SimulationConfig DEFAULT = new SimulationConfig(20, ClockMode.REALTIME, 300, 0,
            Duration.ofSeconds(2), 8, BodyLimits.DEFAULT);

    /** Checks the components; a bad value is refused with an exception that names it. */
    public SimulationConfig {
        if (tickRate < 1 || tickRate > 1000) {
            throw new IllegalArgumentException("tickRate must be 1 to 1000, was " + tickRate);
        }
        if (clock == null) {
            throw new IllegalArgumentException("clock must be realtime or lockstep, was null");
        }
        if (!(timeLimit > 0) || Double.isInfinite(timeLimit)) {
            throw new IllegalArgumentException("timeLimit must be a positive number of seconds, was " + timeLimit);
        }
        if (waitFor < 0) {
            throw new IllegalArgumentException("waitFor must not be negative, was " + waitFor);
        }
        if (lockstepDeadline == null || lockstepDeadline.isNegative() || lockstepDeadline.isZero()) {
            throw new IllegalArgumentException("lockstepDeadline must be positive, was " + lockstepDeadline);
        }
        if (agentsPerSession < 1) {
            throw new IllegalArgumentException("agentsPerSession must be at least 1, was " + agentsPerSession);
        }
        if (bodyLimits == null) {
            throw new IllegalArgumentException("bodyLimits must not be null");
        }
    }

    /** Simulated seconds per tick. */
    public double tickSeconds() {
        return 1.0 / tickRate;
    }
}
