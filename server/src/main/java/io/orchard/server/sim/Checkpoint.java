package io.orchard.server.sim;

import io.orchard.protocol.value.AgentState;
import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.ClockMode;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Score;
import io.orchard.protocol.value.Vec3;
import io.orchard.server.world.World;
import io.orchard.server.world.scenario.Scenario;
import java.util.List;
import java.util.Locale;

/**
 * A whole game at the end of one tick, enough to start it again where it was: the world with the
 * fruit still there, the agents (their bodies, places, headings, what their controllers
 * registered and their resume tokens), the scores, the clock and the seed. The game draws nothing
 * at random but from the seed and the agents' names (where an agent starts), so there is no
 * generator's state to keep. Written by {@link CheckpointFile}; a server resumes from it.
 *
 * @param format       the file format, {@link #FORMAT}
 * @param seed         the seed the game was made from
 * @param tickRate     ticks per simulated second
 * @param clock        realtime or lockstep
 * @param timeLimit    the game's length in simulated seconds
 * @param waitFor      agents the game waits for before it starts
 * @param phase        {@code waiting}, {@code running}, {@code paused} or {@code over}
 * @param tick         the next tick to run
 * @param time         simulated seconds since the start
 * @param fruitAtStart fruit in the world when the game started
 * @param world        the world, with the fruit still there
 * @param agents       the agents waiting to be resumed, then those in the world by name
 * @param scores       every agent's score, best first
 */
public record Checkpoint(int format,
                         long seed,
                         int tickRate,
                         ClockMode clock,
                         double timeLimit,
                         int waitFor,
                         String phase,
                         long tick,
                         double time,
                         int fruitAtStart,
                         Scenario world,
                         List<SavedAgent> agents,
                         List<Score> scores) {

    /** The format this server writes and reads. */
    public static final int FORMAT = 2;

    /** Checks the components; a bad value is refused with an exception that names it. */
    public Checkpoint {
        if (format != FORMAT) {
            throw new IllegalArgumentException("checkpoint format " + format + " is not supported: this server reads "
                    + "format " + FORMAT);
        }
        Checks.present(clock, "clock");
        Checks.present(phase, "phase");
        phaseOf(phase);
        Checks.nonNegative(tick, "tick");
        Checks.nonNegative(time, "time");
        Checks.positive(timeLimit, "timeLimit");
        Checks.present(world, "world");
        agents = Checks.list(agents, "agents");
        scores = Checks.list(scores, "scores");
    }

    /** The game as it is now, as a simulation or a referee holds it. */
    static Checkpoint of(long seed, SimulationConfig config, Phase phase, long tick, double time, int fruitAtStart,
                         World world, List<SavedAgent> agents, List<Score> scores) {
        return new Checkpoint(FORMAT, seed, config.tickRate(), config.clock(), config.timeLimit(), config.waitFor(),
                phase.name().toLowerCase(Locale.ROOT), tick, time, fruitAtStart, world.toScenario(), agents, scores);
    }

    /** The phase as the simulation knows it. */
    Phase gamePhase() {
        return phaseOf(phase);
    }

    private static Phase phaseOf(String phase) {
        try {
            return Phase.valueOf(phase.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("phase must be waiting, running, paused or over, was '" + phase + "'");
        }
    }

    /**
     * An agent as a checkpoint keeps it.
     *
     * @param name        its name
     * @param body        the body in force
     * @param model       its model, if it sent one
     * @param position    where it stood (a walk in progress is not kept)
     * @param heading     its heading in radians
     * @param joints      the joints its controller registered
     * @param timeSensors the time sensors its controller registered
     * @param resumeToken the secret its controller must present to get it back
     */
    public record SavedAgent(String name, Body body, @Nullable ModelSpec model, Vec3 position, double heading,
                             List<String> joints, List<String> timeSensors, String resumeToken) {

        /** Checks the components; a bad value is refused with an exception that names it. */
        public SavedAgent {
            Checks.name(name, "name");
            Checks.present(body, "body");
            Checks.present(position, "position");
            Checks.finite(heading, "heading");
            joints = Checks.list(joints, "joints");
            timeSensors = Checks.list(timeSensors, "timeSensors");
            Checks.text(resumeToken, "resumeToken");
        }

        /** The agent as viewers see it. */
        AgentState state() {
            return new AgentState(name, body, position, heading, model, joints, timeSensors);
        }
    }
}
