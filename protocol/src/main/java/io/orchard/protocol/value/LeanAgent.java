package io.orchard.protocol.value;

import com.fasterxml.jackson.annotation.JsonFormat;

/**
 * Another agent in a lean perception, written as the array
 * {@code [name, distance, bearing, heading, radius]}: a {@link PerceivedAgent} in centimetres and
 * milliradians.
 *
 * @param name     its name
 * @param distance ground distance between centres, in centimetres, 0 or more
 * @param bearing  angle from the perceiver's heading, in milliradians, -3141 to 3142 (3142 is π)
 * @param heading  its heading relative to the perceiver's, in milliradians (3142 is π)
 * @param radius   its body radius, in centimetres, at least 1
 */
@JsonFormat(shape = JsonFormat.Shape.ARRAY)
public record LeanAgent(String name, int distance, int bearing, int heading, int radius) {

    /** Checks the components; a bad value is refused with an exception that names it. */
    public LeanAgent {
        Checks.name(name, "name");
        LeanUnits.distance(distance, "distance");
        LeanUnits.bearing(bearing, "bearing");
        LeanUnits.size(radius, "radius");
    }

    /** The agent as the ordinary perception gives it. */
    public static LeanAgent of(PerceivedAgent agent) {
        return new LeanAgent(agent.name(), LeanUnits.centimetres(agent.at().distance()),
                (int) LeanUnits.milliradians(agent.at().bearing()), (int) LeanUnits.milliradians(agent.heading()),
                LeanUnits.size(agent.radius()));
    }

    /** The agent in units and radians, as the ordinary perception gives it. */
    public PerceivedAgent toPerceived() {
        return new PerceivedAgent(name, LeanUnits.relative(distance, bearing), LeanUnits.radians(heading),
                LeanUnits.units(radius));
    }
}
