package io.orchard.server.sim;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Vec3;
import java.util.List;

/**
 * Everything an agent is, as one part of a world hands it to another ({@link PartialSimulation}):
 * what a {@link Checkpoint.SavedAgent} keeps, and also its walk in progress and its perceptions
 * asked for, so that the agent goes on in the other part as if nothing had happened.
 *
 * @param name                its name
 * @param session             the number of the connection that drives it ({@link ClientSession#id()})
 * @param body                the body in force
 * @param model               its model, if it sent one
 * @param position            where it stands
 * @param heading             its heading in radians
 * @param walk                its walk in progress, or null when it stands
 * @param joints              the joints its controller registered
 * @param timeSensors         the time sensors its controller registered
 * @param resumeToken         the secret that gets it back
 * @param perceptionRequested whether a perception is due at the next tick
 * @param perceptionEvery     its subscription: a perception every so many ticks, 0 for none
 * @param nextPerceptionTick  the tick of the subscription's next perception
 */
public record AgentHandover(String name, long session, Body body, @Nullable ModelSpec model, Vec3 position,
                            double heading, @Nullable Walk walk, List<String> joints, List<String> timeSensors,
                            String resumeToken, boolean perceptionRequested, int perceptionEvery,
                            long nextPerceptionTick) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public AgentHandover {
        Checks.name(name, "name");
        Checks.present(body, "body");
        Checks.present(position, "position");
        Checks.finite(heading, "heading");
        joints = Checks.list(joints, "joints");
        timeSensors = Checks.list(timeSensors, "timeSensors");
        Checks.text(resumeToken, "resumeToken");
    }

    /** This agent standing at {@code at}, its walk as given (null: it stands). */
    public AgentHandover at(Vec3 at, @Nullable Walk walking) {
        return new AgentHandover(name, session, body, model, at, heading, walking, joints, timeSensors, resumeToken,
                perceptionRequested, perceptionEvery, nextPerceptionTick);
    }

    /**
     * This agent without its model: what the parts of a world that simulate it need (a model is for
     * viewers, and may be megabytes).
     */
    public AgentHandover withoutModel() {
        return model == null ? this : new AgentHandover(name, session, body, null, position, heading, walk, joints,
                timeSensors, resumeToken, perceptionRequested, perceptionEvery, nextPerceptionTick);
    }

    /**
     * A walk in progress: a straight segment at constant speed.
     *
     * @param from      where it started
     * @param to        where it ends
     * @param startTime the simulated time it started at
     * @param duration  its simulated seconds
     */
    public record Walk(Vec3 from, Vec3 to, double startTime, double duration) {

        /** Where the walker is at simulated time {@code time}. */
        public Vec3 positionAt(double time) {
            return motion().positionAt(time);
        }

        Motion motion() {
            return new Motion(from, to, startTime, duration);
        }

        static Walk of(Motion motion) {
            return motion == null ? null : new Walk(motion.from(), motion.to(), motion.startTime(), motion.duration());
        }
    }
}
